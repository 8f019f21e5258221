// Map layers of a vehicle's plan for map.js's drawMap(canvas, vehicles, layers, focus): the goto list the glider
// runs (grey, dashed, open squares; a ring on the waypoint its last dialog steered for) and the proposed one (solid, in
// the accent colour, numbered dots a pilot drags). Each layer is (g, { x, y, w, h }); the proposed layer keeps the
// projection it was drawn with, so a pointer on the canvas maps back to a latitude and longitude (drawMap's projection
// is linear in both). Numbers are placed by map.js's placeLabel, off every other label: on the fleet map many vehicles'
// lists share one canvas.
import { placeLabel } from './map.js';

/** What the last drawing of the proposed layer knows: where each waypoint is on screen, and the way back to degrees. */
export class PlanView {
  constructor() {
    this.dots = []; // { i, px, py }
    this.toLat = null;
    this.toLon = null;
    /** True while a waypoint is dragged: the page keeps the map's fit still meanwhile. */
    this.dragging = false;
  }

  /** The proposed waypoint within `radius` CSS pixels of (px, py), nearest first, or -1. */
  hit(px, py, radius = 16) {
    let best = -1, d2 = radius * radius;
    for (const d of this.dots) {
      const e = (d.px - px) ** 2 + (d.py - py) ** 2;
      if (e <= d2) { d2 = e; best = d.i; }
    }
    return best;
  }
}

function inverse(x, y) {
  // x(lon) and y(lat) are a + b·v: two samples give a and b
  const bx = x(1) - x(0), by = y(1) - y(0);
  return { toLon: (px) => (px - x(0)) / bx, toLat: (py) => (py - y(0)) / by };
}

function ink(name, fallback) {
  return getComputedStyle(document.documentElement).getPropertyValue(name).trim() || fallback;
}

function numbered(g, text, px, py, colour, room) {
  placeLabel(g, text, px, py, room, { colour, size: 12, bold: true, gap: 8 });
}

/** The legend's words for the list a glider runs: a dashed leg and an open square, as drawn. */
const GOTO_LEGEND = {
  text: 'goto list',
  mark: (g, x, y) => {
    g.setLineDash([3, 2]); g.beginPath(); g.moveTo(x - 2, y); g.lineTo(x + 12, y); g.stroke(); g.setLineDash([]);
    g.fillStyle = ink('--card', '#fff'); g.fillRect(x + 1, y - 4, 8, 8); g.strokeRect(x + 1, y - 4, 8, 8);
  },
};

/**
 * The list the glider runs, the waypoint it heads for, and its last fix. `options`: `colour` of the list (the fleet map
 * gives each vehicle its own; grey by default), `name` of the vehicle (in data-goto), `leg: false` to leave the fix and
 * the leg from it to a waypoint layer that draws them already. Each waypoint drawn is added to the canvas's data-goto
 * ([name, n, lat, lon, x, y]) and counted in data-plan-waypoints.
 */
export function gliderLayer(model, options = {}) {
  const { colour, name = '', leg = true } = options;
  const layer = (g, { x, y, w, h, placed = [] }) => {
    const c = model.current;
    const grey = colour || ink('--muted', '#666');
    g.save();
    g.strokeStyle = grey; g.fillStyle = grey; g.lineWidth = 1.5; g.setLineDash([6, 4]);
    g.beginPath();
    c.waypoints.forEach((p, n) => (n ? g.lineTo(x(p.lon), y(p.lat)) : g.moveTo(x(p.lon), y(p.lat))));
    g.stroke();
    g.setLineDash([]);
    g.fillStyle = ink('--card', '#fff');
    for (const p of c.waypoints) {
      g.fillRect(x(p.lon) - 5, y(p.lat) - 5, 10, 10);
      g.strokeRect(x(p.lon) - 5, y(p.lat) - 5, 10, 10);
    }
    if (c.heading) {
      g.lineWidth = 2.5; g.strokeStyle = ink('--accent', '#0b57d0');
      g.beginPath(); g.arc(x(c.heading.lon), y(c.heading.lat), 11, 0, 2 * Math.PI); g.stroke();
    }
    if (c.fix && leg) {
      g.fillStyle = ink('--fg', '#222');
      g.beginPath(); g.arc(x(c.fix.lon), y(c.fix.lat), 5, 0, 2 * Math.PI); g.fill();
      if (c.heading) { // the leg it is on
        g.setLineDash([2, 3]); g.strokeStyle = ink('--fg', '#222'); g.lineWidth = 1;
        g.beginPath(); g.moveTo(x(c.fix.lon), y(c.fix.lat)); g.lineTo(x(c.heading.lon), y(c.heading.lat)); g.stroke();
        g.setLineDash([]);
      }
    }
    g.restore();
    for (const p of c.waypoints) numbered(g, `${p.n}`, x(p.lon), y(p.lat), grey, { w, h, placed });
    const data = g.canvas.dataset;
    data.planWaypoints = String(Number(data.planWaypoints || 0) + c.waypoints.length);
    const drawn = JSON.parse(data.goto || '[]');
    for (const p of c.waypoints) drawn.push([name, p.n, p.lat, p.lon, Math.round(x(p.lon)), Math.round(y(p.lat))]);
    data.goto = JSON.stringify(drawn);
  };
  // a getter: the list may come after the layer was made, and drawMap reads the legend when it draws
  Object.defineProperty(layer, 'legend', { get: () => (model.current.waypoints.length ? [GOTO_LEGEND] : []) });
  return layer;
}

/** The proposed list, numbered as the glider counts (0 to N-1); records where each dot went into `view`. */
export function proposedLayer(model, view, selected = () => -1) {
  return (g, { x, y, w, h, placed = [] }) => {
    Object.assign(view, inverse(x, y));
    const colour = ink('--accent', '#0b57d0');
    const pts = model.points();
    view.dots = pts.map((p) => ({ i: p.i, px: x(p.lon), py: y(p.lat) }));
    g.save();
    g.strokeStyle = colour; g.lineWidth = 2.5;
    g.beginPath();
    view.dots.forEach((d, n) => (n ? g.lineTo(d.px, d.py) : g.moveTo(d.px, d.py)));
    g.stroke();
    for (const d of view.dots) {
      g.fillStyle = colour;
      g.beginPath(); g.arc(d.px, d.py, d.i === selected() ? 9 : 7, 0, 2 * Math.PI); g.fill();
      g.lineWidth = 2; g.strokeStyle = ink('--card', '#fff'); g.stroke();
      numbered(g, `${d.i}`, d.px, d.py, colour, { w, h, placed });
    }
    g.restore();
  };
}

/**
 * Dragging on the canvas: a pointer pressed on a proposed waypoint moves it (through the model, so the table follows);
 * a double click (or double tap) on empty map adds one there. `redraw` draws the map again.
 */
export function dragEditor(canvas, model, view, redraw, onSelect = () => {}) {
  let dragging = -1;
  const at = (e) => {
    const r = canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  };
  canvas.style.touchAction = 'none'; // a finger on the map drags the waypoint, not the page
  canvas.addEventListener('pointerdown', (e) => {
    const [px, py] = at(e);
    dragging = view.hit(px, py);
    view.dragging = dragging >= 0;
    if (dragging >= 0) {
      canvas.setPointerCapture(e.pointerId);
      onSelect(dragging);
      e.preventDefault();
    }
  });
  canvas.addEventListener('pointermove', (e) => {
    if (dragging < 0 || !view.toLat) return;
    const [px, py] = at(e);
    model.move(dragging, view.toLat(py), view.toLon(px), 'map');
    redraw();
  });
  const end = () => {
    if (dragging >= 0) { dragging = -1; view.dragging = false; canvas.dataset.dragged = String(Number(canvas.dataset.dragged || 0) + 1); redraw(); }
  };
  canvas.addEventListener('pointerup', end);
  canvas.addEventListener('pointercancel', end);
  canvas.addEventListener('dblclick', (e) => {
    const [px, py] = at(e);
    if (view.hit(px, py) >= 0 || !view.toLat) return;
    model.add(view.toLat(py), view.toLon(px), '', 'map');
    redraw();
  });
}
