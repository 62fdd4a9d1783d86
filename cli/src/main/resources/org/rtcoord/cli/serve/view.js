// The live view: one snapshot when the event stream (re)connects, then updates as they come.
// Exposed on window.rtcoord for tests and for poking at from the console.
'use strict';

const token = new URLSearchParams(location.search).get('token');
const TIMELINE_KEPT = 1000;
const STATES = ['CREATED', 'INACTIVE', 'ACTIVE', 'ERROR', 'UNKNOWN'];

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

cytoscape.use(cytoscapeFcose);

const cy = cytoscape({
  container: document.getElementById('graph'),
  wheelSensitivity: 0.3,
  minZoom: 0.05,
  // A thousand components: draw at one device pixel, and skip labels too small to read (min-zoomed-font-size).
  pixelRatio: 1,
  textureOnViewport: true,
  style: [
    { selector: 'node', style: { label: 'data(label)', 'font-size': 11, 'text-valign': 'center', 'text-halign': 'center', color: '#fff',
      'min-zoomed-font-size': 7 } },
    { selector: 'node.component', style: { shape: 'round-rectangle', width: 'label', height: 26, padding: 8, 'background-color': '#424242' } },
    { selector: 'node.component[state = "ACTIVE"]', style: { 'background-color': '#2e7d32' } },
    { selector: 'node.component[state = "INACTIVE"]', style: { 'background-color': '#1565c0' } },
    { selector: 'node.component[state = "ERROR"]', style: { 'background-color': '#c62828' } },
    { selector: 'node.component[state = "CREATED"]', style: { 'background-color': '#757575' } },
    { selector: 'node.zombie', style: { 'background-color': '#000', 'border-width': 3, 'border-style': 'dashed', 'border-color': '#c62828' } },
    { selector: 'node.context', style: { shape: 'round-rectangle', 'background-color': '#eceff1', 'border-color': '#90a4ae', 'border-width': 1,
      color: '#455a64', 'text-valign': 'top', 'text-halign': 'center', 'font-size': 12 } },
    { selector: 'node.unreachable', style: { 'border-color': '#c62828', 'border-style': 'dashed', 'border-width': 3 } },
    { selector: 'node.manager', style: { shape: 'hexagon', width: 'label', height: 24, padding: 8, 'background-color': '#6a1b9a' } },
    { selector: 'node.external', style: { shape: 'round-rectangle', width: 'label', height: 22, padding: 6, 'background-opacity': 0,
      'border-width': 1, 'border-style': 'dashed', color: '#455a64' } },
    { selector: 'node:selected', style: { 'border-width': 3, 'border-color': '#ffb300' } },
    { selector: 'edge', style: { width: 2, 'curve-style': 'bezier', 'line-color': '#546e7a', 'font-size': 9, color: '#37474f',
      'text-background-color': '#fff', 'text-background-opacity': 0.8, 'min-zoomed-font-size': 7 } },
    { selector: 'edge.data', style: { 'target-arrow-shape': 'triangle', 'target-arrow-color': '#546e7a', label: 'data(label)' } },
    { selector: 'edge.service', style: { 'line-color': '#8d6e63', 'line-style': 'dotted' } },
    { selector: 'edge.hosts', style: { 'line-color': '#ce93d8', 'line-style': 'dashed', width: 1 } },
  ],
});

const view = {
  cy,
  components: new Map(),     // path -> component as last drawn
  shown: {},                 // path -> { state, at (page clock), noticedAt (tree clock) }: when the page showed a state
  coordinatorShownAt: {},    // rule description -> { firings, at }: when the page showed a firing
  loadedAt: Date.now(),      // a reload would change it
  renderedAt: null,
  since: 0,                  // the tree's sequence the last snapshot held: state events up to it are already drawn          // performance.now() when the network was first drawn
  snapshots: 0,
  operable: false,
  coordinator: null,
  selected: null,
};
window.rtcoord = view;

/** The network as cytoscape elements. */
function elementsOf(network) {
  const contexts = new Set(network.contexts.map(c => c.id));
  const parentOf = id => (id && contexts.has(id) ? id : undefined);
  const nodes = [];
  network.contexts.forEach(c => nodes.push({ group: 'nodes', classes: 'context' + (c.reachable ? '' : ' unreachable'),
    data: { id: c.id, label: c.name + (c.reachable ? '' : ' (unreachable)'), parent: parentOf(c.parent) } }));
  network.managers.forEach(m => nodes.push({ group: 'nodes', classes: 'manager', data: { id: m.id, label: m.name, parent: parentOf(m.parent) } }));
  network.components.forEach(c => nodes.push({ group: 'nodes', classes: 'component',
    data: { id: c.id, label: componentLabel(c.name, c.fsm), state: c.state, parent: parentOf(c.parent) } }));
  network.zombies.forEach(z => nodes.push({ group: 'nodes', classes: 'component zombie',
    data: { id: z.id, label: z.name + ' (zombie)', state: 'ZOMBIE', parent: parentOf(z.parent) } }));
  network.external.forEach(x => nodes.push({ group: 'nodes', classes: 'external', data: { id: x.id, label: x.name } }));
  const ids = new Set(nodes.map(n => n.data.id));
  const edges = [];
  network.connections.filter(c => ids.has(c.source) && ids.has(c.target)).forEach(c => edges.push({ group: 'edges', classes: c.kind,
    data: { id: c.kind + ':' + c.source + ':' + c.sourcePort + '->' + c.target + ':' + c.targetPort, source: c.source, target: c.target,
      label: c.label || '' } }));
  network.managers.forEach(m => m.hosts.filter(h => ids.has(h)).forEach(h => edges.push({ group: 'edges', classes: 'hosts',
    data: { id: 'hosts:' + m.id + '->' + h, source: m.id, target: h } })));
  return nodes.concat(edges);
}

/** Draws [network], moving nothing that stays: only a change of shape runs the layout again. */
function drawNetwork(network) {
  document.getElementById('top').textContent = network.top;
  const wanted = elementsOf(network);
  const wantedIds = new Set(wanted.map(e => e.data.id));
  let reshaped = false;
  cy.batch(() => {
    cy.elements().filter(e => !wantedIds.has(e.id())).forEach(e => { cy.remove(e); reshaped = true; });
    wanted.forEach(e => {
      const existing = cy.getElementById(e.data.id);
      if (existing.nonempty() && (existing.data('parent') || undefined) !== e.data.parent && e.group === 'nodes') {
        cy.remove(existing);
      }
      const present = cy.getElementById(e.data.id);
      if (present.empty()) {
        cy.add(e);
        reshaped = true;
      } else {
        present.data(e.data);
        present.classes(e.classes);
      }
    });
  });
  view.components = new Map(network.components.concat(network.zombies.map(z => ({ ...z, state: 'ZOMBIE' }))).map(c => [c.id, c]));
  network.components.forEach(c => noteShown(c.id, c.state));
  listComponents();
  document.getElementById('counts').textContent =
    network.components.length + ' components, ' + network.connections.length + ' connections' +
    (network.zombies.length ? ', ' + network.zombies.length + ' zombies' : '');
  if (reshaped) layout();
}

function layout() {
  const count = cy.nodes().length;
  const running = cy.layout({
    name: 'fcose',
    quality: count > 300 ? 'draft' : 'default',
    randomize: true,
    animate: false,
    nodeDimensionsIncludeLabels: true,
    packComponents: true,
    idealEdgeLength: 80,
    nodeRepulsion: 6000,
  });
  running.one('layoutstop', () => {
    cy.fit(undefined, 20);
    if (view.renderedAt === null) view.renderedAt = performance.now();
    document.body.dataset.rendered = 'true';
  });
  running.run();
}

function noteShown(path, state) {
  const previous = view.shown[path];
  if (!previous || previous.state !== state) view.shown[path] = { state, at: Date.now(), noticedAt: null };
}

function listComponents() {
  const list = document.getElementById('components');
  const items = [...view.components.values()].sort((a, b) => a.id.localeCompare(b.id)).map(c =>
    element('li', { 'data-component': c.id, 'data-state': c.state, title: c.id }, stateBadge(c.state), ' ', c.name));
  list.replaceChildren(...items);
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
  if (item) item.replaceWith(element('li', { 'data-component': path, 'data-state': state, title: path }, stateBadge(state), ' ',
    component ? component.name : path));
  if (view.selected === path) showDetails(path);
}

function timelineEntry(entry) {
  const kind = entry.kind;
  const text = kind === 'log' ? entry.text : entry.event + ': ' + entry.text;
  const li = element('li', { 'data-kind': kind, 'data-source': entry.source, 'data-seq': entry.seq },
    element('span', { class: 'time' }, time(entry.time)), element('span', { class: 'kind' }, kind === 'log' ? entry.source : kind),
    kind === 'log' ? '' : entry.source + '  ', text);
  li.hidden = !visible(li);
  return li;
}

function addToTimeline(entries, replace) {
  const timeline = document.getElementById('timeline');
  const items = entries.map(timelineEntry).reverse();
  if (replace) timeline.replaceChildren(...items); else timeline.prepend(...items);
  while (timeline.children.length > TIMELINE_KEPT) timeline.lastElementChild.remove();
}

function visible(li) {
  const kinds = [...document.querySelectorAll('#filters input[type=checkbox]:checked')].map(i => i.value);
  const search = document.getElementById('search').value.toLowerCase();
  return kinds.includes(li.dataset.kind) && (!search || li.textContent.toLowerCase().includes(search));
}

function refilter() {
  document.querySelectorAll('#timeline li').forEach(li => { li.hidden = !visible(li); });
}
document.querySelectorAll('#filters input').forEach(input => input.addEventListener('input', refilter));

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

async function showDetails(path) {
  view.selected = path;
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
  const parts = [element('h2', {}, 'Component'), element('div', { 'data-details': path }, element('strong', {}, path), ' ',
    report.state ? stateBadge(report.state) : '')];
  if (report.error) {
    parts.push(element('p', { class: 'error' }, report.error));
  } else {
    parts.push(rows([['type', report.typeName], ['version', report.version], ['vendor', report.vendor], ['category', report.category],
      ['description', report.description]].concat(report.fsm ? [['FSM state', report.fsm.state || 'unknown (' + report.fsm.unknownBecause + ')']] : [])));
    if (view.operable) {
      parts.push(element('div', {}, ...['activate', 'deactivate', 'reset'].map(action => {
        const button = element('button', { 'data-action': action }, action);
        button.addEventListener('click', () => operate(path, action));
        return button;
      })));
    }
    parts.push(element('h2', {}, 'Ports'), rows(report.ports.map(p => [p.name + ' (' + p.kind + ')',
      (p.dataType || '') + (p.connections.length ? ' → ' + p.connections.map(c => c.ports.map(e => e.name).join(' ↔ ')).join('; ') : '')])));
    parts.push(element('h2', {}, 'Execution contexts'), rows(report.contexts.map(c => ['#' + c.handle + ' ' + c.kind,
      c.rate + ' Hz, ' + (c.running ? 'running' : 'stopped') + ', ' + c.state + (c.owned ? ', owned' : ', participating')])));
    if (report.configuration) {
      parts.push(element('h2', {}, 'Configuration (active: ' + report.configuration.active + ')'),
        rows(Object.entries(report.configuration.sets).flatMap(([set, values]) =>
          Object.entries(values).map(([name, value]) => [set + '.' + name, value]))));
    }
  }
  details.replaceChildren(...parts);
}

async function operate(path, action) {
  const response = await fetch(api('/api/operate?path=' + encodeURIComponent(path) + '&action=' + action), { method: 'POST' });
  if (!response.ok) alert(action + ' ' + path + ': ' + await response.text());
}

cy.on('tap', 'node.component', event => showDetails(event.target.id()));
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

/** Listens to the server; when it goes away (restarted, say), tries again until it is back. */
function connect() {
  const events = new EventSource(api('/api/events'));
  events.addEventListener('snapshot', message => {
    const snapshot = JSON.parse(message.data);
    view.snapshots++;
    view.operable = snapshot.operable;
    connected(true, 'live' + (snapshot.operable ? ', operable' : ', read-only'));
    drawNetwork(snapshot.network);
    // The network holds the tree's events up to its sequence: older ones that reach the page after it are history.
    view.since = snapshot.network.sequence || 0;
    showCoordinator(snapshot.coordinator);
    addToTimeline(snapshot.events, true);
  });
  events.addEventListener('network', message => {
    const network = JSON.parse(message.data);
    drawNetwork(network);
    view.since = Math.max(view.since, network.sequence || 0);
  });
  events.addEventListener('coordinator', message => showCoordinator(JSON.parse(message.data)));
  events.addEventListener('event', message => {
    const entry = JSON.parse(message.data);
    const news = !entry.sequence || entry.sequence > view.since;
    if (news && entry.event === 'StateChanged' && STATES.includes(entry.new)) applyState(entry.source, entry.new, entry.noticedAt);
    if (news && entry.event === 'FsmStateChanged') applyFsmState(entry.source, entry.new);
    if (entry.event === 'BecameZombie') cy.getElementById(entry.source).addClass('zombie');
    if (entry.event === 'Recovered') cy.getElementById(entry.source).removeClass('zombie');
    addToTimeline([entry], false);
  });
  events.onerror = () => {
    connected(false, 'reconnecting…');
    // A stream the browser gave up on (the server answered with an error) is opened again by hand.
    if (events.readyState === EventSource.CLOSED) setTimeout(connect, 1000);
  };
}
connect();
