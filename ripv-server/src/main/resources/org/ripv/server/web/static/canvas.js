// A canvas made ready to draw at its size on screen in CSS pixels (sharp on any display), cleared to the page's card
// colour: what the map and the trend charts both start with. `ink(name, fallback)` reads a colour of the page's theme.

export function prepareCanvas(canvas, minW, minH, defaultW, defaultH) {
  const css = getComputedStyle(document.documentElement);
  const ink = (name, fallback) => css.getPropertyValue(name).trim() || fallback;
  const box = canvas.getBoundingClientRect();
  const w = Math.max(minW, Math.round(box.width) || defaultW), h = Math.max(minH, Math.round(box.height) || defaultH);
  const dpr = window.devicePixelRatio || 1;
  canvas.width = Math.round(w * dpr);
  canvas.height = Math.round(h * dpr);
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.fillStyle = ink('--card', '#fff');
  g.fillRect(0, 0, w, h);
  return { g, w, h, ink };
}
