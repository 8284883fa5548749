// Scripted input for a sketch page opened by the browser tests (?test=1): moves the mouse
// along ?path=x,y;x,y;... one point a frame after the sketch has started, then posts the
// canvas as a PNG and what the page met to /report/. Without ?test it does nothing.
(function () {
  const q = new URLSearchParams(location.search);
  if (!q.has('test')) return;
  window.scriptedRun = true;   // sketches that read keys move on their own under test
  const report = (name, body) => fetch('/report/' + name, { method: 'POST', body });
  window.addEventListener('error', (e) => report('error', String((e.error && e.error.stack) || e.message)));
  window.addEventListener('unhandledrejection', (e) => report('error', String((e.reason && e.reason.stack) || e.reason)));
  const path = (q.get('path') || '200,150').split(';').map((s) => s.split(',').map(Number));
  let step = 0;
  function tick() {
    const canvas = document.querySelector('canvas');
    if (!canvas || typeof window.mouseX === 'undefined' || !window.frameCount) {
      requestAnimationFrame(tick);
      return;
    }
    if (step < path.length) {
      const [x, y] = path[step++];
      const r = canvas.getBoundingClientRect();
      const at = { clientX: r.left + x, clientY: r.top + y, bubbles: true, pointerType: 'mouse', isPrimary: true };
      // p5 2.x listens for pointer events, p5 1.x for mouse events.
      canvas.dispatchEvent(new PointerEvent('pointermove', at));
      canvas.dispatchEvent(new MouseEvent('mousemove', at));
      setTimeout(() => requestAnimationFrame(tick), 50);
      return;
    }
    setTimeout(() => {
      canvas.toBlob((png) => report('png', png).then(() => report('done', 'frames ' + window.frameCount)));
    }, 100);
  }
  requestAnimationFrame(tick);
})();
