// The map on the operator's tiles (--map-tiles URL) with Leaflet from the server's WebJar: each
// vehicle's whole track (GPS fixes filled, dead-reckoned ones as rings, as on the offline map), its latest fix, a scale,
// and as on the offline map the depth-averaged current at each surfacing (v.currents), the waypoint with the line to it
// (v.waypoint) and the goto list the glider runs (v.goto: PlanModel's `current`, numbered squares on a dashed line), with
// a legend. Labels that would cover another are hidden (the vehicle's name first, then its numbers); what is drawn is
// counted on the map's element (data-points, data-arrows, data-waypoints, data-goto). The CSP lets images come from that
// tile host only.
import * as L from '/webjars/leaflet/1.9.4/dist/leaflet-src.esm.js';
import { vehicleName } from './names.js';
import { fix, colour, ARROW_PX_PER_MPS } from './map.js';

export function tileMap(canvas, template) {
  const css = document.createElement('link');
  css.rel = 'stylesheet';
  css.href = '/webjars/leaflet/1.9.4/dist/leaflet.css';
  document.head.append(css);
  const div = document.createElement('div');
  div.id = canvas.id;
  div.className = 'tiles';
  div.setAttribute('role', 'img');
  div.setAttribute('aria-label', canvas.getAttribute('aria-label') || 'Map');
  canvas.replaceWith(div);
  const map = L.map(div, { worldCopyJump: true, preferCanvas: true }).setView([0, 0], 2);
  const host = new URL(template.replaceAll(/\{[a-z]\}/g, '0')).host;
  L.tileLayer(template, { maxZoom: 18, attribution: `Tiles: ${host}` }).addTo(map);
  L.control.scale({ imperial: false }).addTo(map);
  const legend = L.control({ position: 'bottomleft' });
  legend.onAdd = () => {
    const box = L.DomUtil.create('div', 'map-legend');
    box.dataset.legend = '';
    return box;
  };
  legend.addTo(map);
  const layer = L.layerGroup().addTo(map);
  let fitted = null; // the focus the map was last fitted to
  let last = null; // what was drawn: arrows are sized in pixels, so a zoom draws them again
  map.on('zoomend', () => { if (last) draw(...last); });
  // the permanent labels drawn now: a removed one stays in the DOM while it fades out, and must not hide its successor
  const labels = () => {
    const out = [];
    layer.eachLayer((l) => { const t = l.getTooltip?.(); if (t?.options.permanent && t.getElement()) out.push(t.getElement()); });
    return out;
  };
  map.on('moveend', () => declutter(div, labels()));
  const draw = (vehicles, focus = '') => {
    last = [vehicles, focus];
    layer.clearLayers();
    const all = [];
    let arrows = 0;
    let waypoints = 0;
    const goto = [];
    vehicles.forEach((v, i) => {
      if (!v.track.length) return;
      const c = colour(i);
      const fixes = v.track.map(fix).sort((a, b) => (a.t || 0) - (b.t || 0));
      const points = fixes.map((p) => [p.lat, p.lon]);
      // GPS fixes joined by a solid line, dead-reckoned positions by a dashed one (they differ by the drift).
      L.polyline(fixes.filter((p) => p.gps).map((p) => [p.lat, p.lon]), { color: c, weight: 2 }).addTo(layer);
      L.polyline(fixes.filter((p) => !p.gps).map((p) => [p.lat, p.lon]), { color: c, weight: 1, dashArray: '4 3' }).addTo(layer);
      for (const p of fixes) {
        L.circleMarker([p.lat, p.lon], p.gps ? { radius: 3.5, color: c, fillOpacity: 1, weight: 1 } : { radius: 2.5, color: c, fill: false, weight: 1.5 }).addTo(layer);
      }
      const last = points[points.length - 1];
      for (const p of v.currents || []) arrows += arrow(map, layer, p, c);
      const w = v.waypoint;
      if (w?.to) {
        if (w.from) L.polyline([[w.from.lat, w.from.lon], [w.to.lat, w.to.lon]], { color: c, weight: 1.5, dashArray: '6 4' }).addTo(layer);
        L.circleMarker([w.to.lat, w.to.lon], { radius: 6, color: c, fill: false, weight: 2 })
          .bindTooltip(label(w.words ? `waypoint ${w.words}` : 'waypoint')).addTo(layer);
        waypoints++;
      }
      if (v.goto?.waypoints?.length) {
        const wpts = v.goto.waypoints;
        L.polyline(wpts.map((p) => [p.lat, p.lon]), { color: c, weight: 1.5, dashArray: '6 4' }).addTo(layer);
        for (const p of wpts) {
          L.marker([p.lat, p.lon], { icon: square(c), keyboard: false })
            .bindTooltip(label(`${p.n}`), { permanent: true, direction: 'right', offset: [6, -8], className: 'goto-label' }).addTo(layer);
          goto.push([v.name, p.n, p.lat, p.lon]);
        }
        if (v.goto.heading) L.circleMarker([v.goto.heading.lat, v.goto.heading.lon], { radius: 11, color: accent(), fill: false, weight: 2.5 }).addTo(layer);
      }
      const newest = points[points.length - 1];
      L.circleMarker(newest, { radius: 7, color: c, fillOpacity: 0.9 }).bindTooltip(label(vehicleName(v.name)), { permanent: true }).addTo(layer);
      all.push(...points);
    });
    const mine = vehicles.find((v) => v.name === focus && v.track.length);
    // the fit keeps a vehicle's goto list in view, as the offline map keeps its `also`
    const places = (v) => [...v.track.map(fix).map((p) => [p.lat, p.lon]), ...(v.goto?.waypoints || []).map((p) => [p.lat, p.lon])];
    const bounds = mine ? places(mine) : vehicles.filter((v) => v.track.length).flatMap(places);
    if (bounds.length && fitted !== focus) { map.fitBounds(bounds, { maxZoom: 12, padding: [20, 20] }); fitted = focus; }
    div.dataset.points = String(all.length);
    div.dataset.arrows = String(arrows);
    div.dataset.waypoints = String(waypoints);
    div.dataset.goto = JSON.stringify(goto);
    const words = ['GPS', 'dead-reckoned', ...(goto.length ? ['goto list'] : [])];
    showLegend(legend.getContainer(), words);
    declutter(div, labels());
  };
  return draw;
}

/** The current at a surfacing as an arrow of the offline map's length in pixels (1 if drawn). */
function arrow(map, layer, p, c) {
  if (p.current_e == null || p.current_n == null || p.lat == null) return 0;
  let dx = p.current_e * ARROW_PX_PER_MPS, dy = -p.current_n * ARROW_PX_PER_MPS;
  const len = Math.hypot(dx, dy);
  if (len < 1e-9) return 0;
  const shown = Math.min(80, Math.max(10, len));
  dx *= shown / len; dy *= shown / len;
  const at = (x, y) => map.layerPointToLatLng(L.point(x, y));
  const o = map.latLngToLayerPoint([p.lat, p.lon]);
  const tip = L.point(o.x + dx, o.y + dy);
  const a = Math.atan2(dy, dx);
  L.polyline([at(o.x, o.y), at(tip.x, tip.y)], { color: c, weight: 2 }).addTo(layer);
  L.polygon([at(tip.x, tip.y), at(tip.x - 7 * Math.cos(a - 0.45), tip.y - 7 * Math.sin(a - 0.45)),
    at(tip.x - 7 * Math.cos(a + 0.45), tip.y - 7 * Math.sin(a + 0.45))], { color: c, weight: 1, fillOpacity: 1 }).addTo(layer);
  return 1;
}

/** The page's accent colour: the ring on the waypoint a glider heads for, as the offline map draws it. */
function accent() {
  return getComputedStyle(document.documentElement).getPropertyValue('--accent').trim() || '#0b5cad';
}

/** A waypoint of a goto list: an open square in the vehicle's colour (a Leaflet icon, so it is the same size at every zoom). */
function square(c) {
  const el = document.createElement('span');
  el.className = 'goto-square';
  el.style.borderColor = c; // a property set from script: the CSP forbids style attributes in markup, not this
  return L.divIcon({ html: el, className: 'goto-icon', iconSize: [10, 10] });
}

/** The legend's entries, drawn as the map draws them (the marks are CSS: .map-legend .mark). */
function showLegend(box, words) {
  if (box.dataset.legend === words.join(', ')) return;
  box.dataset.legend = words.join(', ');
  box.replaceChildren(...words.map((w) => {
    const item = document.createElement('span');
    const mark = document.createElement('span');
    mark.className = `mark ${{ GPS: 'gps', 'dead-reckoned': 'dr', 'goto list': 'goto' }[w]}`;
    item.append(mark, ` ${w}`);
    return item;
  }));
}

/**
 * Permanent labels that would cover one shown before them are hidden: vehicles' names come first, then the goto lists'
 * numbers, each list in its order. The boxes shown are the map's data-labels.
 */
function declutter(div, tips) {
  const shown = [];
  tips.sort((a, b) => Number(a.classList.contains('goto-label')) - Number(b.classList.contains('goto-label')));
  for (const t of tips) {
    t.classList.remove('covered');
    const r = t.getBoundingClientRect();
    if (shown.some((o) => r.left < o.right && o.left < r.right && r.top < o.bottom && o.top < r.bottom)) {
      t.classList.add('covered');
    } else {
      shown.push(r);
    }
  }
  const base = div.getBoundingClientRect();
  div.dataset.labels = JSON.stringify(shown.map((r) => [Math.round(r.left - base.left), Math.round(r.top - base.top), Math.round(r.width), Math.round(r.height)]));
}

// Leaflet sets a string tooltip as HTML; a vehicle's name goes in as text.
function label(text) {
  const span = document.createElement('span');
  span.textContent = text;
  return span;
}
