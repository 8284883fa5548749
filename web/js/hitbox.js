import { load } from './teavm-runtime.js';

const teavm = await load(new URL('./hitbox.wasm', import.meta.url).href);
export const raw = teavm.exports;
