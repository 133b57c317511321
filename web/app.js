// The live page: a WebSocket from the console (or neptus-logd) says, every
// second, where every system is, its health, the active alarms and the plans
// running; the page only listens. History (tracks before the page opened)
// comes from /api/track when the console keeps a database.
'use strict';

const token = new URLSearchParams(location.search).get('token');
const withToken = (path) => token ? path + (path.includes('?') ? '&' : '?') + 'token=' + encodeURIComponent(token) : path;
// Track colours: no red or amber, which the page keeps for alarms.
const colours = ['#1e88e5', '#43a047', '#8e24aa', '#00897b', '#3949ab', '#6d4c41', '#546e7a', '#00acc1'];

const map = L.map('map', { zoomControl: true, attributionControl: false, preferCanvas: true }).setView([41.18, -8.7], 13);
const systems = new Map(); // name → { marker, track, colour, fitted }
let coastLayer = null, coastBox = null, fitted = false;
map.createPane('coast').style.zIndex = 340;
const coastRenderer = L.canvas({ pane: 'coast' });

function element(tag, className, text) {
  const e = document.createElement(tag);
  if (className) e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}

function vehicleIcon(colour, heading, name) {
  const html = '<div class="vehicle"><svg viewBox="-14 -14 28 28"><g transform="rotate(' + heading.toFixed(0) + ')">' +
    '<path d="M0,-12 L7,9 L0,5 L-7,9 Z" fill="' + colour + '" stroke="#fff" stroke-width="1.5"/></g></svg></div>';
  return L.divIcon({ html: html, className: '', iconSize: [28, 28], iconAnchor: [14, 14] });
}

function systemEntry(name) {
  let s = systems.get(name);
  if (!s) {
    const colour = colours[systems.size % colours.length];
    s = { colour: colour, track: L.polyline([], { color: colour, weight: 2, opacity: 0.8 }).addTo(map), marker: null };
    systems.set(name, s);
  }
  return s;
}

function loadHistory(name) {
  fetch(withToken('/api/track?system=' + encodeURIComponent(name) + '&from=' + (Date.now() - 6 * 3600e3)))
    .then((r) => r.ok ? r.json() : null)
    .then((answer) => {
      if (!answer || !answer.rows.length) return;
      const s = systemEntry(name);
      const older = answer.rows.map((row) => [row[1], row[2]]);
      s.track.setLatLngs(older.concat(s.track.getLatLngs()));
    })
    .catch(() => {});
}

function loadCoastline() {
  const b = map.getBounds().pad(0.5);
  const box = [b.getWest(), b.getSouth(), b.getEast(), b.getNorth()].map((v) => v.toFixed(3));
  if (b.getEast() - b.getWest() > 10 || b.getNorth() - b.getSouth() > 10) return;
  if (coastBox && coastBox.contains(map.getBounds())) return;
  fetch(withToken('/api/coastline?bbox=' + box.join(',')))
    .then((r) => r.ok ? r.json() : null)
    .then((answer) => {
      if (!answer) return;
      if (coastLayer) coastLayer.remove();
      // (Under a chart: its own coastline is the better one where it has one.)
      coastLayer = L.layerGroup(answer.lines.map((line) => L.polyline(line, { renderer: coastRenderer, color: '#6d5c3d', weight: 1.5,
                                                                              interactive: false })));
      coastLayer.addTo(map);
      coastBox = b;
    })
    .catch(() => {});
}

// The console's nautical chart (when it has one), drawn as its map draws it: depth areas shaded
// against the safety contour, land, contours, the coast, restricted areas and fairways, and
// hazards, buoys, beacons and lights as symbols at the scales their SCAMIN allows. Under the tracks.
map.createPane('chart').style.zIndex = 350;
map.createPane('chartMarks').style.zIndex = 360;
const chartRenderer = L.canvas({ pane: 'chart' });
let chartsShown = false, chartLayer = null, chartBox = null, chartZoom = -1, chartSafety = 5, chartAnswer = null;
let chartAsked = 0; // the last request's number: an older answer arriving later is not drawn
const cssColour = (name) => getComputedStyle(document.documentElement).getPropertyValue('--chart-' + name).trim();

// A symbol's outline by its charted shape, as the console's map draws it (ChartItem's appendOutline),
// 5 pixels a unit, the point at 0,0.
const chartShapes = {
  cross: 'M-5,-5 L5,5 M5,-5 L-5,5',
  flare: 'M0,0 L3,6.2 L4.95,7.4 L7.07,7.07 L7.4,4.95 L6.2,3 Z',
  ring: 'M5,0 A5,5 0 1,0 -5,0 A5,5 0 1,0 5,0 Z',
  conical: 'M-4,3.5 L4,3.5 L0,-5.5 Z',
  can: 'M-3,-3 L3,-3 L3,3 L-3,3 Z',
  spherical: 'M-4.5,2.5 A4.5,4.5 0 0,1 4.5,2.5 Z',
  pillar: 'M-2,3.5 L2,3.5 L1.25,-6.5 L-1.25,-6.5 Z',
  spar: 'M-0.75,3.5 L0.75,3.5 L0.75,-7 L-0.75,-7 Z',
  barrel: 'M5,0 A5,2.75 0 1,0 -5,0 A5,2.75 0 1,0 5,0 Z',
  'super-buoy': 'M6.5,0 A6.5,6.5 0 1,0 -6.5,0 A6.5,6.5 0 1,0 6.5,0 Z M3,0 A3,3 0 1,0 -3,0 A3,3 0 1,0 3,0 Z',
  triangle: 'M-5,0 L5,0 L0,-10 Z',
  stake: 'M0,0 L0,-10 M-2.5,-10 L2.5,-10',
  tower: 'M-2.5,0 L2.5,0 L2.5,-9 L-2.5,-9 Z',
  lattice: 'M-3.5,0 L3.5,0 L1.5,-9 L-1.5,-9 Z M-3.5,0 L1.5,-9 M3.5,0 L-1.5,-9',
  pile: 'M-1.25,0 L1.25,0 L1.25,-7.5 L-1.25,-7.5 Z',
  cairn: 'M-4.5,0 L4.5,0 L0,-6 Z',
};

// A sector light's legs and arc (mark.sector: directions from the light, degrees true, clockwise
// from the first to the second), 25 and 35 pixels out, as the console's map draws them.
function sectorPaths(sector) {
  const at = (degrees, r) => (r * Math.sin(degrees * Math.PI / 180)).toFixed(2) + ',' + (-r * Math.cos(degrees * Math.PI / 180)).toFixed(2);
  const from = sector[0], to = sector[1] > from ? sector[1] : sector[1] + 360; // charts::LightSector::span()
  const legs = 'M0,0 L' + at(from, 35) + ' M0,0 L' + at(to, 35);
  if (to - from >= 360) // all round: an arc's ends may not meet, so two halves
    return { legs: legs, arc: 'M' + at(from, 25) + ' A25,25 0 1,1 ' + at(from + 180, 25) + ' A25,25 0 1,1 ' + at(from, 25) };
  return { legs: legs, arc: 'M' + at(from, 25) + ' A25,25 0 ' + (to - from > 180 ? 1 : 0) + ',1 ' + at(to, 25) };
}

// A shape's extent (its path's bounding box), measured once in a hidden SVG.
const svgNs = 'http://www.w3.org/2000/svg';
const shapeBoxes = {};
function shapeBox(d) {
  if (!shapeBoxes[d]) {
    const svg = document.createElementNS(svgNs, 'svg'), path = document.createElementNS(svgNs, 'path');
    svg.style.position = 'absolute';
    svg.style.visibility = 'hidden';
    path.setAttribute('d', d);
    svg.appendChild(path);
    document.body.appendChild(svg);
    const b = path.getBBox();
    shapeBoxes[d] = { x: b.x, y: b.y, width: b.width, height: b.height };
    svg.remove();
  }
  return shapeBoxes[d];
}

// A buoy's or beacon's bands (mark.bands: its colour pattern and colours), filling its shape as the
// console's map fills it: top to bottom, left to right, from the upper left, or in quarters.
let bandClips = 0;
function bandsSvg(d, bands, colours) {
  const b = shapeBox(d), n = bands.colours.length, id = 'bands' + (++bandClips);
  const fill = (i) => colours[bands.colours[i % n]];
  const rect = (x, y, w, h, i) => '<rect x="' + x + '" y="' + y + '" width="' + w + '" height="' + h + '" fill="' + fill(i) + '"/>';
  let rects = '';
  if (bands.pattern === 'vertical') {
    for (let i = 0; i < n; ++i) rects += rect(b.x + b.width * i / n, b.y, b.width / n, b.height, i);
  } else if (bands.pattern === 'squared') {
    const w = b.width / 2, h = b.height / 2;
    rects = rect(b.x, b.y, w, h, 0) + rect(b.x + w, b.y, w, h, 1) + rect(b.x, b.y + h, w, h, 1) + rect(b.x + w, b.y + h, w, h, 0);
  } else if (bands.pattern === 'diagonal') { // stacked along the lower right diagonal, from the shape's upper left
    const corners = [[b.x, b.y], [b.x + b.width, b.y], [b.x, b.y + b.height], [b.x + b.width, b.y + b.height]].map(([x, y]) => (x + y) / Math.SQRT2);
    const first = Math.min(...corners), span = Math.max(...corners) - first;
    for (let i = 0; i < n; ++i) rects += rect(first + span * i / n, -20, span / n, 40, i);
    rects = '<g transform="rotate(45)">' + rects + '</g>';
  } else {
    for (let i = 0; i < n; ++i) rects += rect(b.x, b.y + b.height * i / n, b.width, b.height / n, i);
  }
  return '<defs><clipPath id="' + id + '"><path d="' + d + '"/></clipPath></defs><g clip-path="url(#' + id + ')">' + rects + '</g>';
}

function chartSymbol(mark, colours) {
  const c = mark.kind === 'hazard' ? colours.hazard : mark.colour ? colours[mark.colour] : colours.aid;
  const shape = chartShapes[mark.shape] || chartShapes.ring;
  const side = mark.sector ? 80 : 24;
  const stroke = (d, colour, width) => '<path d="' + d + '" fill="none" stroke="' + colour + '" stroke-width="' + width + '"/>';
  let sector = '';
  if (mark.sector) { // the legs in the chart's black (the hazards' colour), the arc in the light's colour over an outline in it
    const paths = sectorPaths(mark.sector);
    sector = stroke(paths.legs, colours.hazard, 1.2) + stroke(paths.arc, colours.hazard, 5.8) + stroke(paths.arc, c, 1.8);
  }
  const svg = '<svg viewBox="' + -side / 2 + ' ' + -side / 2 + ' ' + side + ' ' + side + '" width="' + side + '" height="' + side
    + '">' + (mark.bands && mark.shape !== 'stake' ? bandsSvg(shape, mark.bands, colours) : '') + sector
    + stroke(shape, c, 1.8) + '</svg>';
  return L.divIcon({ html: svg, className: 'chart-mark', iconSize: [side, side], iconAnchor: [side / 2, side / 2] });
}

function drawChart() {
  const answer = chartAnswer;
  if (!answer) return;
  if (chartLayer) chartLayer.remove();
  const colours = {};
  for (const name of ['deep', 'medium', 'shallow', 'drying', 'land', 'contour', 'safety', 'coast', 'hazard', 'aid', 'restricted',
                      'red', 'green', 'yellow'])
    colours[name] = cssColour(name);
  const layers = [];
  const lineStyles = { contour: { color: colours.contour, weight: 1 }, safety: { color: colours.safety, weight: 2 },
                       coast: { color: colours.coast, weight: 1.5 }, restricted: { color: colours.restricted, weight: 1.5, dashArray: '6 4' },
                       fairway: { color: colours.contour, weight: 1.5, dashArray: '10 7' } };
  // Usage band after usage band, overview first: where cells overlap, the best band covers the rest.
  for (const band of answer.layers) {
    for (const shade of ['deep', 'medium', 'shallow', 'drying', 'land'])
      for (const polygon of band.areas[shade])
        layers.push(L.polygon(polygon, { renderer: chartRenderer, stroke: false, fillColor: colours[shade], fillOpacity: 1, interactive: false }));
    for (const [kind, style] of Object.entries(lineStyles))
      for (const line of band.lines[kind])
        layers.push(L.polyline(line, Object.assign({ renderer: chartRenderer, interactive: false }, style)));
  }
  // The scale for OGC's standard 0.28 mm rendering pixel, as the console's map works it out.
  const scale = 156543.03 * Math.cos(map.getCenter().lat * Math.PI / 180) / Math.pow(2, map.getZoom()) / 0.00028;
  for (const mark of answer.marks) {
    if (mark.scamin > 0 ? scale > mark.scamin : map.getZoom() < 11) continue;
    const words = [mark.what, mark.name, mark.depth !== undefined ? 'charted depth ' + mark.depth + ' m' : ''].filter((x) => x).join(' · ');
    layers.push(L.marker([mark.lat, mark.lon], { pane: 'chartMarks', icon: chartSymbol(mark, colours), title: words, keyboard: false }));
  }
  chartLayer = L.layerGroup(layers).addTo(map);
  document.getElementById('chart-status').textContent = answer.cells.length
    ? 'chart ' + answer.cells.join(', ') + ' · safety contour ' + answer.safetyContour + ' m · not for navigation' : '';
}

function loadChart() {
  const b = map.getBounds().pad(0.5);
  if (b.getEast() - b.getWest() > 10 || b.getNorth() - b.getSouth() > 10) return;
  if (chartBox && chartBox.contains(map.getBounds()) && chartZoom === map.getZoom()) return;
  const box = [b.getWest(), b.getSouth(), b.getEast(), b.getNorth()].map((v) => v.toFixed(4));
  const zoom = map.getZoom();
  const asked = ++chartAsked;
  fetch(withToken('/api/chart?bbox=' + box.join(',') + '&safety=' + chartSafety))
    .then((r) => r.ok ? r.json() : null)
    .then((answer) => {
      if (!answer || asked !== chartAsked) return;
      chartAnswer = answer;
      chartBox = b;
      chartZoom = zoom;
      drawChart();
    })
    .catch(() => {});
}

// The last hour's alarm and plan events, from the operation's database (newest first).
let historyTimers = [], alarmKey = '';
function loadEvents() {
  const from = '?from=' + (Date.now() - 3600e3);
  Promise.all([fetch(withToken('/api/alarms' + from)), fetch(withToken('/api/plans' + from))])
    // A failed query (the database busy or away) keeps what is shown rather than say "nothing".
    .then((replies) => Promise.all(replies.map((r) => { if (!r.ok) throw new Error(r.status); return r.json(); })))
    .then(([alarms, plans]) => {
      const detail = (...parts) => parts.filter((x) => x).join(' · ');
      const events = alarms.rows.map((a) => ({ t: a.t, level: a.level, text: a.origin + ' ' + a.event, detail: detail(a.message, a.console) }))
        .concat(plans.rows.map((p) => ({ t: p.t, level: 'Info', text: p.system + ': plan ' + p.plan + ' ' + p.event + (p.maneuver ? ' ' + p.maneuver : ''),
                                         detail: detail(p.detail, p.console) })))
        .sort((a, b) => b.t - a.t).slice(0, 30);
      const list = document.getElementById('history');
      list.replaceChildren();
      for (const e of events) {
        const item = element('li', 'alarm event');
        const when = new Date(e.t).toISOString().slice(11, 19);
        item.append(element('span', 'badge level-' + e.level, when), element('span', 'what', e.text), element('span', 'msg', e.detail));
        list.append(item);
      }
      if (!events.length) list.append(element('li', 'empty', 'nothing in the last hour'));
    })
    .catch(() => {});
}
// After the console has written them: within a second as a rule, later when
// its disk is busy (a write waits for the disk), so asked again twice.
function eventsSoon() {
  historyTimers.forEach(clearTimeout);
  historyTimers = [1000, 3000, 6000].map((ms) => setTimeout(loadEvents, ms));
}

function showState(state) {
  const list = document.getElementById('systems');
  const plans = document.getElementById('plans');
  list.replaceChildren();
  plans.replaceChildren();
  const bounds = [];
  for (const sys of state.systems) {
    const s = systemEntry(sys.name);
    if (sys.lat !== undefined) {
      const here = [sys.lat, sys.lon];
      bounds.push(here);
      const last = s.track.getLatLngs().at(-1);
      if (!last || last.lat !== sys.lat || last.lng !== sys.lon) s.track.addLatLng(here);
      if (!s.marker) {
        s.marker = L.marker(here, { icon: vehicleIcon(s.colour, sys.heading, sys.name), title: sys.name }).addTo(map);
        s.marker.bindTooltip(sys.name, { permanent: true, direction: 'right', offset: [12, 0], className: 'label' });
      } else {
        s.marker.setLatLng(here);
        s.marker.setIcon(vehicleIcon(s.colour, sys.heading, sys.name));
      }
    }
    const item = element('li', 'sys ' + sys.health);
    item.dataset.system = sys.name;
    item.append(element('span', 'dot'), element('span', 'name', sys.name), element('span', 'age', sys.age < 2 ? 'now' : sys.age.toFixed(0) + ' s ago'));
    const facts = [sys.kind || '?', sys.health];
    if (sys.lat !== undefined) facts.push(sys.lat.toFixed(5) + ', ' + sys.lon.toFixed(5), 'depth ' + sys.depth.toFixed(1) + ' m',
                                         'heading ' + sys.heading.toFixed(0) + '°', sys.speed.toFixed(1) + ' m/s');
    item.append(element('span', 'detail', facts.join(' · ')));
    item.addEventListener('click', () => { if (sys.lat !== undefined) map.setView([sys.lat, sys.lon], Math.max(map.getZoom(), 15)); });
    list.append(item);
    if (sys.plan && sys.plan.state === 'EXECUTING') {
      const p = element('li', 'plan');
      p.dataset.system = sys.name;
      p.append(element('div', 'name', sys.name + ': ' + sys.plan.id), element('div', 'detail', 'maneuver ' + sys.plan.maneuver + ' · ' + sys.plan.progress.toFixed(0) + ' %'));
      const bar = element('div', 'bar');
      const fill = element('div');
      fill.style.width = Math.max(0, Math.min(100, sys.plan.progress)) + '%';
      bar.append(fill);
      p.append(bar);
      plans.append(p);
    }
  }
  if (!state.systems.length) list.append(element('li', 'empty', 'none heard yet'));
  if (!plans.children.length) plans.append(element('li', 'empty', 'none running'));
  document.getElementById('system-count').textContent = state.systems.length ? '(' + state.systems.length + ')' : '';

  const alarms = document.getElementById('alarms');
  alarms.replaceChildren();
  for (const a of state.alarms) {
    const item = element('li', 'alarm' + (a.acknowledged ? ' ack' : ''));
    item.dataset.origin = a.origin;
    item.append(element('span', 'badge level-' + a.level, a.level), element('span', 'what', a.origin), element('span', 'msg', a.message));
    alarms.append(item);
  }
  if (!state.alarms.length) alarms.append(element('li', 'empty', 'none'));
  const key = state.alarms.map((a) => a.origin + a.level + a.acknowledged).join('|') +
              state.systems.map((s) => s.plan ? s.plan.state + s.plan.id + s.plan.maneuver : '').join('|');
  if (key !== alarmKey && !document.getElementById('history-section').hidden) eventsSoon();
  alarmKey = key;
  document.getElementById('alarm-count').textContent = state.alarms.length ? '(' + state.alarms.length + ')' : '';
  if (!fitted && bounds.length) {
    map.fitBounds(L.latLngBounds(bounds).pad(0.6), { maxZoom: 15 });
    fitted = true;
  }
}

function connect() {
  const link = document.getElementById('link');
  const socket = new WebSocket((location.protocol === 'https:' ? 'wss://' : 'ws://') + location.host + withToken('/ws'));
  socket.onopen = () => { link.textContent = 'live'; link.className = 'link up'; };
  socket.onclose = () => {
    link.textContent = 'connection lost: retrying'; link.className = 'link down';
    setTimeout(connect, 2000);
  };
  socket.onmessage = (event) => {
    const message = JSON.parse(event.data);
    if (message.type === 'hello') {
      document.getElementById('title').textContent = message.title;
      document.title = message.title + ' · live';
      if (message.tiles) L.tileLayer(message.tiles, { maxZoom: 19 }).addTo(map);
      if (message.charts && !chartsShown) { // (a reconnection's hello adds nothing)
        chartsShown = true;
        chartSafety = message.safetyDepth;
        map.on('moveend', loadChart);
        loadChart();
        window.matchMedia('(prefers-color-scheme: dark)').addEventListener('change', drawChart);
      }
      if (message.history) {
        document.getElementById('history-section').hidden = false;
        loadEvents();
        setInterval(loadEvents, 30000);
      }
      for (const [name, line] of Object.entries(message.tracks)) {
        systemEntry(name).track.setLatLngs(line);
        if (message.history) loadHistory(name);
      }
    } else if (message.type === 'state') {
      showState(message);
      document.body.dataset.updated = String(message.t);
    }
  };
}

L.control.scale({ imperial: false }).addTo(map);
map.on('moveend', loadCoastline);
loadCoastline();
connect();
