import { vehicleName } from './names.js';
// An offline map: latitude/longitude grid lines with each vehicle's track and latest fix. No tiles, no internet.
export function drawMap(canvas, vehicles) {
  const g = canvas.getContext('2d');
  const w = canvas.width, h = canvas.height;
  const css = getComputedStyle(document.documentElement);
  g.fillStyle = css.getPropertyValue('--card') || '#fff';
  g.fillRect(0, 0, w, h);
  const points = vehicles.flatMap((v) => v.track);
  let [minLat, maxLat, minLon, maxLon] = [-60, 60, -180, 180];
  if (points.length) {
    minLat = Math.min(...points.map((p) => p[0])); maxLat = Math.max(...points.map((p) => p[0]));
    minLon = Math.min(...points.map((p) => p[1])); maxLon = Math.max(...points.map((p) => p[1]));
    const pad = Math.max(0.02, (maxLat - minLat) * 0.2, (maxLon - minLon) * 0.2);
    minLat -= pad; maxLat += pad; minLon -= pad; maxLon += pad;
  }
  const x = (lon) => ((lon - minLon) / (maxLon - minLon)) * w;
  const y = (lat) => h - ((lat - minLat) / (maxLat - minLat)) * h;
  const step = niceStep(Math.max(maxLat - minLat, maxLon - minLon) / 5);
  g.strokeStyle = css.getPropertyValue('--line') || '#ccc';
  g.fillStyle = css.getPropertyValue('--muted') || '#555';
  g.font = '14px sans-serif';
  g.lineWidth = 1;
  for (let lat = Math.ceil(minLat / step) * step; lat <= maxLat; lat += step) {
    g.beginPath(); g.moveTo(0, y(lat)); g.lineTo(w, y(lat)); g.stroke();
    g.fillText(`${lat.toFixed(step < 1 ? 2 : 0)}°`, 4, y(lat) - 3);
  }
  for (let lon = Math.ceil(minLon / step) * step; lon <= maxLon; lon += step) {
    g.beginPath(); g.moveTo(x(lon), 0); g.lineTo(x(lon), h); g.stroke();
    g.fillText(`${lon.toFixed(step < 1 ? 2 : 0)}°`, x(lon) + 3, h - 4);
  }
  vehicles.forEach((v, i) => {
    if (!v.track.length) return;
    const colour = `hsl(${(i * 67) % 360} 70% 40%)`;
    g.strokeStyle = colour; g.fillStyle = colour; g.lineWidth = 2;
    g.beginPath();
    v.track.forEach(([lat, lon], k) => (k ? g.lineTo(x(lon), y(lat)) : g.moveTo(x(lon), y(lat))));
    g.stroke();
    const [lat, lon] = v.track[v.track.length - 1];
    g.beginPath(); g.arc(x(lon), y(lat), 6, 0, 2 * Math.PI); g.fill();
    g.fillText(vehicleName(v.name), x(lon) + 8, y(lat) - 8);
  });
  canvas.dataset.points = String(points.length);
}

function niceStep(raw) {
  const p = Math.pow(10, Math.floor(Math.log10(raw || 1)));
  const n = raw / p;
  return (n < 1.5 ? 1 : n < 3.5 ? 2 : n < 7.5 ? 5 : 10) * p;
}
