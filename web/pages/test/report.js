// What a test page tells the browser test that opened it (web/test/java/hitbox/web/Browser.java).
export async function report(name, body) {
  await fetch('/report/' + name, { method: 'POST', body });
}

export function reportError(e) {
  return report('error', String((e && e.stack) || e));
}

window.addEventListener('error', (e) => reportError(e.error || e.message));
window.addEventListener('unhandledrejection', (e) => reportError(e.reason));
