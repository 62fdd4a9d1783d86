// The live view: one snapshot when the event stream (re)connects, then updates as they come.
// Exposed on window.rtcoord for tests and for poking at from the console.
'use strict';

const token = new URLSearchParams(location.search).get('token');
const TIMELINE_KEPT = 1000;
const STATES = ['CREATED', 'INACTIVE', 'ACTIVE', 'ERROR', 'UNKNOWN'];
const LEVELS = ['FATAL', 'ERROR', 'WARN', 'INFO', 'DEBUG', 'TRACE', 'VERBOSE', 'PARANOID']; // OpenRTM-aist's, most severe first
const PORT = 10;           // a port's size on screen
const ROW = 14;            // a port's row on a component
const TITLE = 20;          // a component's name above its ports
const TRAFFIC_SHOWN = 600; // how long a connector stays lit after data moved
const PORTS_FROM_ZOOM = 0.35; // below this zoom, ports are too small to see and are not drawn
const PORTS_UP_TO = 400;      // components in a system drawn with their ports

/** [path] with the token, when the page was opened with one. */
function api(path) {
  return token ? path + (path.includes('?') ? '&' : '?') + 'token=' + encodeURIComponent(token) : path;
}

function element(tag, attributes, ...children) {
  const node = document.createElement(tag);
  Object.entries(attributes || {}).forEach(([key, value]) => {
    if (value !== null && value !== undefined) node.setAttribute(key, value);
  });
  children.flat().forEach(child => node.append(child instanceof Node ? child : document.createTextNode(String(child ?? ''))));
  return node;
}

function stateBadge(state) {
  return element('span', { class: 'state state-' + state }, state);
}

function time(iso) {
  return iso ? new Date(iso).toLocaleTimeString([], { hour12: false }) + '.' + String(new Date(iso).getMilliseconds()).padStart(3, '0') : '';
}

const cy = cytoscape({
  container: document.getElementById('graph'),
  wheelSensitivity: 0.3,
  minZoom: 0.02,
  maxZoom: 4,
  // Placed by rule (layout.js): dragging one node would pull it off its ports.
  autoungrabify: true,
  // A thousand components: draw at one device pixel, and skip labels too small to read (min-zoomed-font-size).
  pixelRatio: 1,
  textureOnViewport: true,
  style: [
    { selector: 'node', style: { label: 'data(label)', 'font-size': 11, 'text-valign': 'center', 'text-halign': 'center', color: '#fff',
      'min-zoomed-font-size': 6 } },
    { selector: 'node.component', style: { shape: 'round-rectangle', width: 'data(width)', height: 'data(height)', 'text-valign': 'top',
      'text-margin-y': 17, 'background-color': '#424242', 'border-width': 1, 'border-color': '#263238' } },
    { selector: 'node.component[state = "ACTIVE"]', style: { 'background-color': '#2e7d32' } },
    { selector: 'node.component[state = "INACTIVE"]', style: { 'background-color': '#1565c0' } },
    { selector: 'node.component[state = "ERROR"]', style: { 'background-color': '#c62828' } },
    { selector: 'node.component[state = "CREATED"]', style: { 'background-color': '#757575' } },
    { selector: 'node.zombie', style: { 'background-color': '#000', 'border-width': 3, 'border-style': 'dashed', 'border-color': '#c62828',
      'text-valign': 'center', 'text-margin-y': 0 } },
    { selector: 'node.port', style: { shape: 'rectangle', width: PORT, height: PORT, 'background-color': '#eceff1', 'border-width': 1,
      'border-color': '#263238', label: 'data(label)', 'font-size': 8, color: '#fff', 'text-valign': 'center', 'text-margin-x': 'data(labelShift)',
      'text-halign': 'data(labelSide)', 'min-zoomed-font-size': 8 } },
    { selector: 'node.port.out', style: { shape: 'triangle', 'background-color': '#fff59d' } },
    { selector: 'node.port.service', style: { shape: 'diamond', 'background-color': '#d7ccc8', label: '' } },
    { selector: 'node.port.far', style: { visibility: 'hidden' } },
    { selector: 'node.context', style: { shape: 'round-rectangle', 'background-color': '#eceff1', 'border-color': '#90a4ae', 'border-width': 1,
      color: '#455a64', 'text-valign': 'top', 'text-halign': 'center', 'font-size': 12, padding: LAYOUT.padding } },
    { selector: 'node.unreachable', style: { 'border-color': '#c62828', 'border-style': 'dashed', 'border-width': 3 } },
    { selector: 'node.manager', style: { shape: 'hexagon', width: 'data(width)', height: 'data(height)', 'background-color': '#6a1b9a' } },
    { selector: 'node.external', style: { shape: 'round-rectangle', width: 'data(width)', height: 'data(height)', 'background-opacity': 0,
      'border-width': 1, 'border-style': 'dashed', color: '#455a64' } },
    { selector: 'node.logged-error', style: { 'outline-width': 4, 'outline-color': '#ff1744', 'outline-offset': 2 } },
    { selector: 'node:selected', style: { 'border-width': 3, 'border-color': '#ffb300' } },
    { selector: 'node.faded, edge.faded', style: { opacity: 0.2 } },
    { selector: 'node.match', style: { 'border-width': 3, 'border-color': '#ff6f00' } },
    { selector: 'edge', style: { width: 2, 'curve-style': 'bezier', 'line-color': '#546e7a', 'font-size': 9, color: '#37474f',
      'text-background-color': '#fff', 'text-background-opacity': 0.8, 'min-zoomed-font-size': 7 } },
    { selector: 'edge.data', style: { 'target-arrow-shape': 'triangle', 'target-arrow-color': '#546e7a', label: 'data(label)' } },
    { selector: 'edge.service', style: { 'line-color': '#8d6e63', 'line-style': 'dashed' } },
    { selector: 'edge.hosts', style: { 'line-color': '#ce93d8', 'line-style': 'dotted', width: 1, 'curve-style': 'straight' } },
    { selector: 'edge.traffic', style: { 'line-color': '#ff8f00', 'target-arrow-color': '#ff8f00', width: 4 } },
  ],
});

const view = {
  cy,
  components: new Map(),     // path -> component as last drawn
  shown: {},                 // path -> { state, at (page clock), noticedAt (tree clock) }: when the page showed a state
  coordinatorShownAt: {},    // rule description -> { firings, at }: when the page showed a firing
  loadedAt: Date.now(),      // a reload would change it
  renderedAt: null,          // performance.now() when the network was first drawn
  since: 0,                  // the tree's sequence the last snapshot held: state events up to it are already drawn
  snapshots: 0,
  layouts: 0,                // how often the structure changed and everything was placed again
  operable: false,
  coordinator: null,
  selected: null,
  shape: null,               // what the layout was computed from: only a change to it moves anything
  network: null,             // the network as last drawn
  steered: false,            // whether the user zoomed or panned
  aspect: null,              // the width over the height the layout aims at: the graph's, when first drawn
  portsFar: null,            // whether the ports are left out, the view being zoomed out too far to see them
  held: [],                  // timeline entries that came while the timeline was paused
  replay: null,              // the recording replayed, and where in it the page is
  lastErrors: {},            // path -> the last ERROR or FATAL record it sent (its timeline entry), until a newer one
};
window.rtcoord = view;

/** The width [text] takes in the graph's font at [size] pixels. */
const measure = (() => {
  const context = document.createElement('canvas').getContext('2d');
  const family = getComputedStyle(document.body).fontFamily;
  return (text, size) => {
    context.font = size + 'px ' + family;
    return context.measureText(text).width;
  };
})();

/** A port's node id: its component's path and its name. */
function portId(component, port) {
  return component + '#' + port;
}

/**
 * A component's body and where its ports sit on it, as RTSystemEditor draws one: in-ports on the left
 * edge, out-ports on the right, service ports along the bottom, the name on top. Sized from the names
 * alone, so that a change of state or FSM state never moves anything.
 */
function componentShape(c) {
  const ins = c.ports.filter(p => p.kind === 'in');
  const outs = c.ports.filter(p => p.kind === 'out');
  const services = c.ports.filter(p => p.kind === 'service');
  const widest = ports => Math.max(0, ...ports.map(p => measure(p.name, 8)));
  const width = Math.ceil(Math.max(measure(c.name, 11) + (c.fsm ? 70 : 0) + 16, widest(ins) + widest(outs) + 3 * PORT + 12,
    services.length * (PORT + 8) + 16, 60));
  const height = TITLE + Math.max(ins.length, outs.length, 1) * ROW + 4;
  const offsets = new Map();
  ins.forEach((p, i) => offsets.set(p.name, { x: -width / 2, y: -height / 2 + TITLE + i * ROW + ROW / 2, side: 'right' }));
  outs.forEach((p, i) => offsets.set(p.name, { x: width / 2, y: -height / 2 + TITLE + i * ROW + ROW / 2, side: 'left' }));
  services.forEach((p, i) => offsets.set(p.name, { x: -width / 2 + 12 + i * (PORT + 8), y: height / 2, side: 'center' }));
  return { width, height, offsets };
}

/** The network as nodes to place (with their sizes) and edges, each node's parent a naming context. */
function elementsOf(network) {
  const contexts = new Set(network.contexts.map(c => c.id));
  const parentOf = id => (id && contexts.has(id) ? id : undefined);
  const nodes = [];
  const leaves = [];
  const ports = [];
  network.contexts.forEach(c => nodes.push({ group: 'nodes', classes: 'context' + (c.reachable ? '' : ' unreachable'),
    data: { id: c.id, label: c.name + (c.reachable ? '' : ' (unreachable)'), parent: parentOf(c.parent) } }));
  const box = (id, label, size, height, parent, classes, extra) => {
    const width = Math.ceil(measure(label, size) + 20);
    nodes.push({ group: 'nodes', classes, data: { id, label, parent: parentOf(parent), width, height, ...extra } });
    leaves.push({ id, parent: parentOf(parent), width, height });
  };
  network.managers.forEach(m => box(m.id, m.name, 11, 26, m.parent, 'manager' + loggedClass(m.id)));
  network.components.forEach(c => {
    const shape = componentShape(c);
    nodes.push({ group: 'nodes', classes: 'component' + loggedClass(c.id), data: { id: c.id, label: componentLabel(c.name, c.fsm), state: c.state,
      parent: parentOf(c.parent), width: shape.width, height: shape.height } });
    // The ports stick out of the body by half their size: the layout leaves room for them.
    leaves.push({ id: c.id, parent: parentOf(c.parent), width: shape.width + PORT, height: shape.height + PORT / 2 });
    // Port nodes multiply what is drawn several times over: beyond a few hundred components, connectors join the components.
    if (network.components.length > PORTS_UP_TO) return;
    c.ports.forEach(p => {
      const at = shape.offsets.get(p.name);
      ports.push({ id: portId(c.id, p.name), component: c.id, dx: at.x, dy: at.y });
      nodes.push({ group: 'nodes', classes: 'port ' + p.kind, data: { id: portId(c.id, p.name), component: c.id, parent: parentOf(c.parent),
        label: p.kind === 'service' ? '' : p.name, name: p.name, kind: p.kind, dataType: p.dataType || '', interfaces: p.interfaces || [],
        labelSide: at.side, labelShift: at.side === 'right' ? 2 : at.side === 'left' ? -2 : 0 } });
    });
  });
  network.zombies.forEach(z => box(z.id, z.name + ' (zombie)', 11, 26, z.parent, 'component zombie', { state: 'ZOMBIE' }));
  network.external.forEach(x => box(x.id, x.name, 11, 24, undefined, 'external'));
  const ids = new Set(nodes.map(n => n.data.id));
  const end = (vertex, port) => (ids.has(portId(vertex, port)) ? portId(vertex, port) : vertex);
  const edges = [];
  network.connections.filter(c => ids.has(c.source) && ids.has(c.target)).forEach(c => {
    const source = end(c.source, c.sourcePort);
    const target = end(c.target, c.targetPort);
    edges.push({ group: 'edges', classes: c.kind, data: { id: c.kind + ':' + source + '->' + target, source, target, label: c.label || '',
      connection: c.source + ':' + c.sourcePort + '->' + c.target + ':' + c.targetPort } });
  });
  network.managers.forEach(m => m.hosts.filter(h => ids.has(h)).forEach(h => edges.push({ group: 'edges', classes: 'hosts',
    data: { id: 'hosts:' + m.id + '->' + h, source: m.id, target: h } })));
  // Data flows left to right; a manager comes before what it hosts.
  const ranks = flowRanks(leaves.map(l => l.id), network.connections.filter(c => c.kind === 'data').map(c => [c.source, c.target]));
  const managers = new Set(network.managers.map(m => m.id));
  leaves.forEach(l => { l.rank = managers.has(l.id) ? -1 : ranks.get(l.id); });
  return { nodes, edges, leaves, ports };
}

/** Where every node goes: the leaves as the layout places them, each port on its component's edge. */
function positionsOf(elements, contexts) {
  // Shaped like the window the first time; kept for good, so that the same system is placed the same way.
  if (!view.aspect) view.aspect = Math.min(3, Math.max(0.5, cy.width() / Math.max(1, cy.height())));
  const positions = layoutSystem(elements.leaves, contexts, view.aspect);
  elements.ports.forEach(p => {
    const at = positions.get(p.component);
    positions.set(p.id, { x: at.x + p.dx, y: at.y + p.dy });
  });
  return positions;
}

/**
 * Draws [network]. Positions are computed from its shape alone (what is there, inside what, with
 * which ports and connections): a change of state moves nothing, a change of shape places everything
 * again, the same way each time. Every node gets its position as it is added, so that each edge has
 * its ends, and its box, from the first frame.
 */
function drawNetwork(network) {
  document.getElementById('top').textContent = network.top;
  const elements = elementsOf(network);
  const wanted = elements.nodes.concat(elements.edges);
  const shape = JSON.stringify([elements.nodes.map(n => [n.data.id, n.data.parent, n.data.width, n.data.height]),
    elements.edges.map(e => e.data.id)]);
  const reshaped = shape !== view.shape;
  const positions = reshaped ? positionsOf(elements, network.contexts) : null;
  const wantedIds = new Set(wanted.map(e => e.data.id));
  cy.batch(() => {
    cy.elements().filter(e => !wantedIds.has(e.id())).remove();
    elements.nodes.forEach(e => {
      const existing = cy.getElementById(e.data.id);
      // A node's parent cannot change in place: it is added again.
      if (existing.nonempty() && (existing.data('parent') || undefined) !== e.data.parent) existing.remove();
    });
    wanted.forEach(e => {
      const present = cy.getElementById(e.data.id);
      if (present.empty()) {
        cy.add(e.group === 'nodes' && positions && positions.has(e.data.id) ? { ...e, position: positions.get(e.data.id) } : e);
      } else {
        present.data(e.data);
        present.classes(e.classes);
      }
    });
    if (positions) cy.nodes().forEach(n => { if (positions.has(n.id())) n.position(positions.get(n.id())); });
  });
  view.network = network;
  // Copies: state events change them, and a replay draws the same network again from the start.
  view.components = new Map(network.components.map(c => ({ ...c })).concat(network.zombies.map(z => ({ ...z, state: 'ZOMBIE', ports: [] })))
    .map(c => [c.id, c]));
  network.components.forEach(c => noteShown(c.id, c.state));
  listComponents();
  document.getElementById('counts').textContent =
    network.components.length + ' components, ' + network.connections.length + ' connections' +
    (network.zombies.length ? ', ' + network.zombies.length + ' zombies' : '');
  if (reshaped) {
    view.portsFar = null;
    view.shape = shape;
    view.layouts++;
    if (!view.steered) fit();
    find(document.getElementById('find').value);
    portsAtZoom();
  }
  if (view.renderedAt === null) view.renderedAt = performance.now();
  document.body.dataset.rendered = 'true';
}

/**
 * Ports are a few pixels when the view is zoomed out far: they are left out then (their connectors
 * stay), which keeps a thousand components quick to draw.
 */
function portsAtZoom() {
  const far = cy.zoom() < PORTS_FROM_ZOOM;
  if (far === view.portsFar) return;
  view.portsFar = far;
  cy.batch(() => { if (far) cy.nodes('.port').addClass('far'); else cy.nodes('.port').removeClass('far'); });
}
cy.on('zoom', portsAtZoom);

/** The whole system in the window, unless the user moved the view. */
function fit() {
  cy.fit(undefined, 20);
}

/** Highlights the components whose path or type holds [text], fades the rest and brings them into view. */
function find(text) {
  const wanted = text.trim().toLowerCase();
  cy.batch(() => {
    cy.elements().removeClass('faded match');
    if (!wanted) return;
    const matches = cy.nodes('.component').filter(n => n.id().toLowerCase().includes(wanted) ||
      ((view.components.get(n.id()) || {}).type || '').toLowerCase().includes(wanted));
    const ports = cy.nodes('.port').filter(p => matches.some(m => m.id() === p.data('component')));
    matches.addClass('match');
    cy.elements().not(matches).not(ports).not('.context').addClass('faded');
    matches.connectedEdges().removeClass('faded');
    ports.connectedEdges().removeClass('faded');
  });
  const matched = cy.nodes('.match');
  if (matched.nonempty()) cy.fit(matched, 60);
  document.getElementById('found').textContent = wanted ? matched.length + ' found' : '';
}

/** A connector's data moved: it lights up for a moment. */
function showTraffic(path, port) {
  const connectors = cy.getElementById(portId(path, port)).connectedEdges();
  connectors.addClass('traffic');
  clearTimeout(view.trafficTimers[portId(path, port)]);
  view.trafficTimers[portId(path, port)] = setTimeout(() => connectors.removeClass('traffic'), TRAFFIC_SHOWN);
}
view.trafficTimers = {};

function noteShown(path, state) {
  const previous = view.shown[path];
  if (!previous || previous.state !== state) view.shown[path] = { state, at: Date.now(), noticedAt: null };
}

function listComponents() {
  const list = document.getElementById('components');
  const items = [...view.components.values()].sort((a, b) => a.id.localeCompare(b.id)).map(c => componentItem(c.id, c.name, c.state));
  list.replaceChildren(...items);
}

/** A component's line in the list: its state, its name, and its last error when it logged one. */
function componentItem(path, name, state) {
  const error = view.lastErrors[path];
  return element('li', { 'data-component': path, 'data-state': state, title: path }, stateBadge(state), ' ', name,
    error ? element('span', { class: 'logged-error', title: errorText(error) }, ' ⚠') : '');
}

/** The class that marks a node whose sender logged an ERROR or FATAL record. */
function loggedClass(path) {
  return view.lastErrors[path] ? ' logged-error' : '';
}

/** An error record in a line: its level, when it was logged, its logger and message. */
function errorText(record) {
  return record.level + ' at ' + time(record.loggedAt) + ' (' + (record.logger || '-') + '): ' + record.message;
}

/** Keeps [record] as its sender's last error when it is one and is not older than the one kept; returns whether it did. */
function keepError(record) {
  if (record.kind !== 'record' || LEVELS.indexOf(record.level) > LEVELS.indexOf('ERROR')) return false;
  const kept = view.lastErrors[record.source];
  if (kept && Date.parse(kept.loggedAt) > Date.parse(record.loggedAt)) return false;
  view.lastErrors[record.source] = record;
  return true;
}

/** A record that came: an error marks its sender's box, list line and panel. */
function noteRecord(record) {
  if (!keepError(record)) return;
  const path = record.source;
  cy.getElementById(path).addClass('logged-error');
  const component = view.components.get(path);
  const item = document.querySelector('#components li[data-component="' + CSS.escape(path) + '"]');
  if (item && component) item.replaceWith(componentItem(path, component.name, component.state));
  if (view.selected === path) showDetails(path);
}

/** A component's label: its name, and its FSM's state when known. */
function componentLabel(name, fsm) {
  return fsm && fsm.state ? name + ' [' + fsm.state + ']' : name;
}

/** An FSM state the tree noticed, shown at once as the component's label says it. */
function applyFsmState(path, state) {
  const component = view.components.get(path);
  if (!component) return;
  component.fsm = { state, unknownBecause: null };
  const node = cy.getElementById(path);
  if (!node.empty()) node.data('label', componentLabel(component.name, component.fsm));
  if (view.selected === path) showDetails(path);
}

/** A state the tree noticed, shown at once: the next network read agrees with it. */
function applyState(path, state, noticedAt) {
  const node = cy.getElementById(path);
  if (node.empty() || !node.hasClass('component')) return;
  node.data('state', state);
  const component = view.components.get(path);
  if (component) component.state = state;
  view.shown[path] = { state, at: Date.now(), noticedAt };
  const item = document.querySelector('#components li[data-component="' + CSS.escape(path) + '"]');
  if (item) item.replaceWith(componentItem(path, component ? component.name : path, state));
  if (view.selected === path) showDetails(path);
}

function timelineEntry(entry) {
  const kind = entry.kind;
  const li = kind === 'record' ? recordEntry(entry) : element('li', { 'data-kind': kind, 'data-source': entry.source, 'data-seq': entry.seq },
    element('span', { class: 'time' }, time(entry.time)), element('span', { class: 'kind' }, kind === 'log' ? entry.source : kind),
    kind === 'log' ? '' : entry.source + '  ', kind === 'log' ? entry.text : entry.event + ': ' + entry.text);
  li.entry = entry;
  li.hidden = !visible(li);
  return li;
}

/** A component's log record as RTSystemEditor's log view shows one: when it was logged, its level, who, what. */
function recordEntry(entry) {
  const origin = [entry.host, entry.pid && 'pid ' + entry.pid, entry.manager && 'manager ' + entry.manager].filter(Boolean).join(', ');
  return element('li', { 'data-kind': 'record', 'data-level': entry.level, 'data-source': entry.source, 'data-seq': entry.seq,
    title: 'from ' + (origin || 'an unknown sender') + ', tag ' + entry.tag },
  element('span', { class: 'time' }, time(entry.loggedAt)), element('span', { class: 'kind' }, 'record'),
  element('span', { class: 'level level-' + entry.level }, entry.level), ' ', entry.source + '  ', (entry.logger || '-') + ': ' + entry.message);
}

/**
 * Adds [entries] to the timeline, newest on top, or puts them in its place when [replace]. While the
 * timeline is paused, new entries wait in view.held and come in on resuming.
 */
function addToTimeline(entries, replace) {
  if (replace) view.held = [];
  if (!replace && document.getElementById('pause').checked) {
    view.held.push(...entries);
    document.getElementById('held').textContent = view.held.length + ' waiting';
    return;
  }
  const timeline = document.getElementById('timeline');
  const items = entries.map(timelineEntry).reverse();
  if (replace) timeline.replaceChildren(...items); else timeline.prepend(...items);
  while (timeline.children.length > TIMELINE_KEPT) timeline.lastElementChild.remove();
}

function visible(li) {
  const kinds = [...document.querySelectorAll('#filters input[type=checkbox][value]:checked')].map(i => i.value);
  const search = document.getElementById('search').value.toLowerCase();
  const level = document.getElementById('level').value;
  const selectedOnly = document.getElementById('only-selected').checked;
  return kinds.includes(li.dataset.kind) && (!search || li.textContent.toLowerCase().includes(search)) &&
    (!level || li.dataset.kind !== 'record' || LEVELS.indexOf(li.dataset.level) <= LEVELS.indexOf(level)) &&
    (!selectedOnly || li.dataset.source === view.selected);
}

function refilter() {
  document.querySelectorAll('#timeline li').forEach(li => { li.hidden = !visible(li); });
}
document.querySelectorAll('#filters input[value], #search').forEach(input => input.addEventListener('input', refilter));
document.querySelectorAll('#level, #only-selected').forEach(input => input.addEventListener('change', refilter));

/** A CSV field: quoted, its quotes doubled, when it holds a comma, a quote or a line break. */
function csvField(value) {
  const text = value === null || value === undefined ? '' : String(value);
  return /[",\r\n]/.test(text) ? '"' + text.replace(/"/g, '""') + '"' : text;
}

/** The log records the timeline shows, oldest first, as CSV with a header line, as RTSystemEditor's log view exports them. */
function recordsCsv() {
  const shown = [...document.querySelectorAll('#timeline li[data-kind=record]:not([hidden])')].reverse().map(li => li.entry);
  return [['time', 'level', 'path', 'logger', 'message', 'pid', 'host', 'manager']]
    .concat(shown.map(r => [r.loggedAt, r.level, r.source, r.logger, r.message, r.pid, r.host, r.manager]))
    .map(row => row.map(csvField).join(',') + '\r\n').join('');
}
view.recordsCsv = recordsCsv;

document.getElementById('csv').addEventListener('click', () => {
  const link = element('a', { href: URL.createObjectURL(new Blob([recordsCsv()], { type: 'text/csv' })), download: 'rtcoord-records.csv' });
  link.click();
  setTimeout(() => URL.revokeObjectURL(link.href), 1000);
});
document.getElementById('pause').addEventListener('change', event => {
  if (event.target.checked) return;
  const held = view.held;
  view.held = [];
  document.getElementById('held').textContent = '';
  addToTimeline(held, false);
});

function showCoordinator(state) {
  view.coordinator = state;
  const section = document.getElementById('coordinator');
  section.hidden = !state;
  if (!state) return;
  const now = Date.now();
  document.getElementById('rules').replaceChildren(element('h2', {}, 'Rules'), ...state.rules.map(rule => {
    const shown = view.coordinatorShownAt[rule.description];
    if (!shown || shown.firings !== rule.firings) view.coordinatorShownAt[rule.description] = { firings: rule.firings, at: now, lastFired: rule.lastFired };
    return element('div', { class: 'rule', 'data-rule': rule.description, 'data-firings': rule.firings, 'data-failures': rule.failures },
      element('div', {}, 'on ' + rule.description),
      element('div', { class: 'muted' }, rule.firings ? 'fired ' + rule.firings + '×, last at ' + time(rule.lastFired) + ' by ' + rule.lastEvent : 'not fired yet'),
      rule.failures ? element('div', { class: 'error' }, rule.failures + ' failures, last: ' + rule.lastFailure) : '');
  }));
  document.getElementById('machines').replaceChildren(...(state.machines.length ? [element('h2', {}, 'Mode machines')] : []),
    ...state.machines.map(machine => element('div', { class: 'machine', 'data-machine': machine.name, 'data-mode': machine.mode },
      element('div', {}, machine.name + ': ', element('span', { class: 'mode' }, machine.mode || '(not started)')),
      modeTree(machine, null),
      element('ol', { class: 'muted' }, ...machine.history.slice(-8).reverse().map(move =>
        element('li', {}, time(move.at) + ' ' + (move.from || 'start') + ' → ' + move.to + ' on ' + move.trigger))),
      machine.unconsumed ? element('div', { class: 'muted' }, machine.unconsumed + ' events unconsumed') : '')));
  document.getElementById('supervisors').replaceChildren(...(state.supervisors.length ? [element('h2', {}, 'Supervisors')] : []),
    ...state.supervisors.map(s => element('div', { class: 'supervisor', 'data-supervisor': s.name, 'data-restarts': s.restarts },
      element('div', {}, s.name + ' (' + s.strategy + '): ' + s.restarts + ' restarts' + (s.lastRestarted ? ', last ' + s.lastRestarted + ' at ' + time(s.lastRestart) : '')),
      element('ul', { class: 'muted' }, ...s.children.map(child => element('li', {}, child))),
      s.waitingUntil ? element('div', {}, 'back-off ' + s.backoffMillis + ' ms, until ' + time(s.waitingUntil)) : '',
      s.escalation ? element('div', { class: 'error' }, 'escalated: ' + s.escalation) : '')));
  if (state.failures) section.dataset.failures = state.failures;
}

/**
 * The component panel: profile, ports with their connectors, configuration sets (the active one
 * marked), execution contexts with rate and state; with --operate, a control for each operation.
 */
/** [machine]'s modes below [parent] as nested lists, the modes on the active path marked. */
function modeTree(machine, parent) {
  const modes = (machine.modes || []).filter(m => (m.parent || null) === parent);
  if (!modes.length) return '';
  const active = m => machine.mode === m.path || (machine.mode || '').startsWith(m.path + '/');
  return element('ul', { class: 'modes' }, ...modes.map(m => element('li', { 'data-mode-path': m.path, class: active(m) ? 'active' : '' },
    m.name, modeTree(machine, m.path))));
}

async function showDetails(path) {
  view.selected = path;
  if (document.getElementById('only-selected').checked) refilter();
  const details = document.getElementById('details');
  let report;
  try {
    const response = await fetch(api('/api/component?path=' + encodeURIComponent(path)));
    report = response.ok ? await response.json() : { path, error: await response.text() };
  } catch (e) {
    report = { path, error: String(e) };
  }
  if (view.selected !== path) return;
  const rows = pairs => element('table', {}, ...pairs.map(([k, v]) => element('tr', {}, element('td', {}, k), element('td', {}, v))));
  const button = (label, action, parameters) => {
    const control = element('button', { 'data-action': action }, label);
    control.addEventListener('click', () => operate(path, action, typeof parameters === 'function' ? parameters() : parameters));
    return view.operable ? control : '';
  };
  const parts = [element('h2', {}, 'Component'), element('div', { 'data-details': path }, element('strong', {}, path), ' ',
    report.state ? stateBadge(report.state) : '')];
  if (view.lastErrors[path]) parts.push(element('p', { class: 'error', 'data-last-error': path }, 'last ' + errorText(view.lastErrors[path])));
  if (report.error) {
    parts.push(element('p', { class: 'error' }, report.error));
    details.replaceChildren(...parts);
    return;
  }
  parts.push(rows([['type', report.typeName], ['version', report.version], ['vendor', report.vendor], ['category', report.category],
    ['description', report.description]].concat(report.fsm ? [['FSM state', report.fsm.state || 'unknown (' + report.fsm.unknownBecause + ')']] : [])));
  if (view.operable) parts.push(element('div', {}, ...['activate', 'deactivate', 'reset', 'exit'].map(action => button(action, action, {}))));
  parts.push(element('h2', {}, 'Ports'), element('table', { class: 'ports' }, ...report.ports.map(p => element('tr', { 'data-port': p.name },
    element('td', {}, p.name + ' (' + p.kind + ')', element('div', { class: 'muted' }, p.dataType || p.interfaces.map(i => i.instanceName + ': ' + i.typeName).join(', '))),
    element('td', {}, ...p.connections.map(c => element('div', { 'data-connector': c.id },
      c.ports.map(e => e.path || e.name).join(' ↔ '), ' ',
      element('span', { class: 'muted' }, Object.entries(c.properties).filter(([k]) => /interface_type|dataflow_type|subscription_type/.test(k))
        .map(([k, v]) => k.replace('dataport.', '') + '=' + v).join(' ')),
      button('disconnect', 'disconnect', { port: p.name, connector: c.id }))))))));
  if (view.operable) parts.push(element('p', { class: 'hint' }, 'Drag from a port to another to connect them.'));
  parts.push(element('h2', {}, 'Execution contexts'), rows(report.contexts.map(c => ['#' + c.handle + ' ' + c.kind,
    c.rate + ' Hz, ' + (c.running ? 'running' : 'stopped') + ', ' + c.state + (c.owned ? ', owned' : ', participating')])));
  if (report.configuration) {
    const active = report.configuration.active;
    parts.push(element('h2', {}, 'Configuration'));
    Object.entries(report.configuration.sets).forEach(([set, values]) => {
      parts.push(element('div', { class: 'set', 'data-set': set, 'data-active': String(set === active) },
        element('strong', {}, set), set === active ? ' (active)' : ' ', set === active ? '' : button('activate', 'activate-set', { set })));
      parts.push(rows(Object.entries(values).map(([name, value]) => {
        if (!view.operable) return [name, value];
        const input = element('input', { value, 'data-parameter': set + '.' + name, 'aria-label': set + '.' + name });
        return [name, element('span', {}, input, button('set', 'set', () => ({ set, name, value: input.value })))];
      })));
    });
  }
  details.replaceChildren(...parts);
}

/** Asks the server to do [action] on [path] with [parameters]; says why when it refuses or fails. */
async function operate(path, action, parameters) {
  const query = Object.entries(parameters || {}).map(([k, v]) => '&' + k + '=' + encodeURIComponent(v)).join('');
  const response = await fetch(api('/api/operate?path=' + encodeURIComponent(path) + '&action=' + action + query), { method: 'POST' });
  const text = await response.text();
  view.lastOperation = { path, action, parameters, status: response.status, text };
  const said = document.getElementById('operation');
  said.textContent = action + ' ' + path + ': ' + text;
  said.className = response.ok ? 'muted' : 'error';
  if (response.ok && view.selected === path) showDetails(path);
  return response.status;
}
view.operate = operate;

// With --operate, a drag from one port to another connects them: the view does not pan meanwhile.
cy.on('tapstart', 'node.port', event => {
  if (!view.operable || view.replay) return;
  view.dragFrom = event.target;
  cy.userPanningEnabled(false);
});
cy.on('tapend', event => {
  const from = view.dragFrom;
  view.dragFrom = null;
  cy.userPanningEnabled(true);
  const to = event.target;
  if (!from || to === cy || !to.hasClass('port') || to.id() === from.id()) return;
  const [out, into] = from.hasClass('in') ? [to, from] : [from, to];
  operate(out.data('component'), 'connect', { port: out.data('name'), to: into.data('component') + ':' + into.data('name') });
});

cy.on('tap', 'node.component', event => showDetails(event.target.id()));
cy.on('tap', 'node.port', event => showDetails(event.target.data('component')));

// A port tells its name, kind and data type (or its interfaces) under the pointer.
const tip = document.getElementById('tip');
cy.on('mouseover', 'node.port', event => {
  const port = event.target.data();
  showTip(event, port.name + ' (' + port.kind + ')' + (port.dataType ? ': ' + port.dataType : '') +
    (port.interfaces.length ? ': ' + port.interfaces.join(', ') : ''));
});
// A box marked for an error tells the last one.
cy.on('mouseover', 'node.logged-error', event => {
  const error = view.lastErrors[event.target.id()];
  if (error) showTip(event, 'last ' + errorText(error));
});
cy.on('mouseout', 'node.port, node.logged-error', () => { tip.hidden = true; });

function showTip(event, text) {
  tip.textContent = text;
  const at = event.renderedPosition;
  const graph = cy.container().getBoundingClientRect();
  tip.style.left = (graph.left + at.x + 12) + 'px';
  tip.style.top = (graph.top + at.y + 12) + 'px';
  tip.hidden = false;
}

// Once the user zooms or pans, a change of structure leaves the view where they put it.
['wheel', 'mousedown', 'touchstart'].forEach(kind => cy.container().addEventListener(kind, () => { view.steered = true; }, { passive: true }));
document.getElementById('zoom-in').addEventListener('click', () => zoomBy(1.25));
document.getElementById('zoom-out').addEventListener('click', () => zoomBy(0.8));
document.getElementById('zoom-fit').addEventListener('click', () => { view.steered = false; fit(); });
document.getElementById('find').addEventListener('input', event => find(event.target.value));

function zoomBy(factor) {
  view.steered = true;
  cy.zoom({ level: cy.zoom() * factor, renderedPosition: { x: cy.width() / 2, y: cy.height() / 2 } });
}
document.getElementById('components').addEventListener('click', event => {
  const item = event.target.closest('li[data-component]');
  if (!item) return;
  cy.$(':selected').unselect();
  cy.getElementById(item.dataset.component).select();
  showDetails(item.dataset.component);
});

function connected(yes, text) {
  const status = document.getElementById('connection');
  status.dataset.connected = String(yes);
  status.textContent = text;
}

/** What the server sent, applied to the page: the same for a live stream, a snapshot alone and a replay. */
function apply(kind, data) {
  if (kind === 'snapshot') {
    view.snapshots++;
    view.operable = data.operable;
    // The errors the recent events hold, drawn with the network.
    view.lastErrors = {};
    data.events.forEach(keepError);
    drawNetwork(data.network);
    // The network holds the tree's events up to its sequence: older ones that reach the page after it are history.
    view.since = data.network.sequence || 0;
    showCoordinator(data.coordinator);
    addToTimeline(data.events, true);
  } else if (kind === 'network') {
    drawNetwork(data);
    view.since = Math.max(view.since, data.sequence || 0);
  } else if (kind === 'coordinator') {
    showCoordinator(data);
  } else if (kind === 'event') {
    const news = !data.sequence || data.sequence > view.since;
    if (news && data.event === 'StateChanged' && STATES.includes(data.new)) applyState(data.source, data.new, data.noticedAt);
    if (news && data.event === 'FsmStateChanged') applyFsmState(data.source, data.new);
    if (data.event === 'PortTraffic' && !view.replay) showTraffic(data.source, data.port);
    if (data.event === 'BecameZombie') cy.getElementById(data.source).addClass('zombie');
    if (data.event === 'Recovered') cy.getElementById(data.source).removeClass('zombie');
    if (data.kind === 'record') noteRecord(data);
    addToTimeline([data], false);
  }
}

/**
 * Listens to the server; when it goes away (restarted, say), tries again until it is back. A server
 * replaying a recording sends it whole instead, once.
 */
function connect() {
  const events = new EventSource(api('/api/events'));
  events.addEventListener('snapshot', message => {
    const snapshot = JSON.parse(message.data);
    connected(true, 'live' + (snapshot.operable ? ', operable' : ', read-only'));
    apply('snapshot', snapshot);
  });
  ['network', 'coordinator', 'event'].forEach(kind => events.addEventListener(kind, message => apply(kind, JSON.parse(message.data))));
  events.addEventListener('replay', message => {
    events.close();
    connected(true, 'replay');
    startReplay(JSON.parse(message.data));
  });
  events.onerror = () => {
    connected(false, 'reconnecting…');
    // A stream the browser gave up on (the server answered with an error) is opened again by hand.
    if (events.readyState === EventSource.CLOSED) setTimeout(connect, 1000);
  };
}

/**
 * The page as it stands, once: no event stream, so that a headless browser taking a picture with a
 * virtual time budget is not held by a request that never ends (`?once`).
 */
async function showOnce() {
  const response = await fetch(api('/api/snapshot'));
  const snapshot = await response.json();
  connected(true, 'as of ' + time(snapshot.serverTime));
  apply('snapshot', snapshot);
}

if (new URLSearchParams(location.search).has('once')) showOnce(); else connect();
