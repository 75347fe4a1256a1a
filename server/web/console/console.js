// The operator's console (docs/console.md): sign in, pick a map, watch the robots live
// from the WebSocket feed, give goals and initial poses by clicking the map, abort tasks.
// Plain ES2017 over api.js, frames.js, map_view.js, fleet_view.js; no build step.
'use strict';

const OPEN_TASK_STATES = ['assigned', 'acknowledged', 'active'];
const TASKS_SHOWN = 100;

const app = {
  session: null,       // {user, role, csrf}
  maps: {},            // name -> the GET /api/maps entry
  mapName: null,
  robots: {},          // name -> robot state (REST/WebSocket object)
  tasks: {},           // id -> task
  mode: null,          // 'goal' | 'pose' | null
  ws: null,
  lastError: null,     // the last refused request: {status, code, message}
  loadSeq: 0,          // drops replies of a map load a newer one superseded
};

const $ = (id) => document.getElementById(id);
const fmt = (v, d) => (v === null || v === undefined ? '–' : Number(v).toFixed(d === undefined ? 2 : d));
const isOperator = () => app.session !== null && app.session.role === 'operator';

const view = new MapView('map', onMapClick);
const fleet = new FleetView(view, selectRobot);

// ---- messages ------------------------------------------------------------------

let messageTimer = null;
function showMessage(text, kind) {
  const m = $('message');
  m.textContent = text;
  m.className = kind || 'info';
  m.hidden = false;
  clearTimeout(messageTimer);
  messageTimer = setTimeout(() => { m.hidden = true; }, kind === 'error' ? 20000 : 6000);
}

// A refused request, as the server said it (SPEC 4: 403 for an inspector's write).
function showFailure(what, e) {
  if (e instanceof ApiFailure) {
    app.lastError = { status: e.status, code: e.code, message: e.message };
    if (e.status === 401 && app.session) { sessionLost(); return; }
    const lead = e.status === 422 ? what + ' refused' : e.status === 403 ? what + ' forbidden' : what + ' failed';
    showMessage(lead + ' (' + e.status + ' ' + e.code + '): ' + e.message, 'error');
  } else {
    app.lastError = { status: 0, code: 'network', message: String(e) };
    showMessage(what + ' failed: ' + e, 'error');
  }
}

// ---- session ---------------------------------------------------------------------

async function boot() {
  try {
    const s = await fleetApi.get('/api/session');
    await start(s);
  } catch (e) {
    showLogin();
  }
}

function showLogin(error) {
  $('login').hidden = false;
  $('login-error').hidden = !error;
  $('login-error').textContent = error || '';
  $('login-password').value = '';
  $('login-user').focus();
}

async function onLoginSubmit(ev) {
  ev.preventDefault();
  const user = $('login-user').value.trim();
  const password = $('login-password').value;
  $('login-submit').disabled = true;
  try {
    let s = await fleetApi.post('/api/login', { user: user, password: password });
    if (!s || !s.csrf) s = await fleetApi.get('/api/session');
    await start(s);
  } catch (e) {
    const why = e instanceof ApiFailure
      ? (e.status === 401 ? 'Wrong user or password.'
        : e.status === 403 ? 'This account may not sign in here (operators and inspectors only).' : e.message)
      : String(e);
    showLogin(why);
  } finally {
    $('login-submit').disabled = false;
  }
}

async function start(s) {
  app.session = { user: s.user, role: s.role, csrf: s.csrf };
  fleetApi.csrf = s.csrf;
  $('login').hidden = true;
  $('who-user').textContent = s.user;
  $('who-role').textContent = s.role;
  $('who-role').className = 'role ' + s.role;
  document.body.classList.toggle('read-only', !isOperator());
  await loadMaps();
  await refreshTasks();
  connectFeed();
}

async function logout() {
  try { await fleetApi.post('/api/logout'); } catch (e) { /* the session is gone either way */ }
  stop();
  showLogin();
}

function sessionLost() {
  stop();
  showLogin('Your session ended; sign in again.');
}

function stop() {
  app.session = null;
  fleetApi.csrf = null;
  if (app.ws) { app.ws.onclose = null; app.ws.close(); app.ws = null; }
  app.robots = {};
  app.tasks = {};
  $('robots').textContent = '';
  $('tasks').textContent = '';
  fleet.removeAll();
  setMode(null);
  updateControls();
}

// ---- maps ------------------------------------------------------------------------

async function loadMaps() {
  let list = [];
  try { list = await fleetApi.get('/api/maps'); } catch (e) { showFailure('Loading the maps', e); return; }
  app.maps = {};
  const sel = $('map-select');
  sel.textContent = '';
  for (const m of list) {
    app.maps[m.name] = m;
    const o = document.createElement('option');
    o.value = m.name;
    // A CRS may be a whole WKT: in the tooltip, not in the list.
    o.textContent = m.name + (m.georeferenced ? ' (georeferenced)' : '');
    if (m.crs) o.title = m.crs;
    sel.appendChild(o);
  }
  const wanted = new URLSearchParams(location.search).get('map');
  const name = app.maps[wanted] ? wanted : app.maps[app.mapName] ? app.mapName : list.length ? list[0].name : null;
  if (name) { sel.value = name; await showMap(name, false); }
}

// Draws map name in the map frame, or in WGS 84 when asked and georeferenced.
async function showMap(name, wgs84) {
  const seq = ++app.loadSeq;
  const entry = app.maps[name];
  app.mapName = name;
  $('crs-toggle').hidden = !(entry && entry.georeferenced);
  $('crs-wgs84').checked = Boolean(wgs84);
  const base = apiPath`/api/maps/${name}`;
  try {
    const walls = await fleetApi.get(base);
    let frame = mapFrame;
    let shown = walls;
    if (wgs84) {
      shown = await fleetApi.get(base + '?crs=wgs84');
      frame = makeWgs84Frame(walls, shown);
      if (!frame.usable) showMessage('WGS 84 view: map-frame clicks disabled (the frames do not fit to 25 cm).', 'error');
    }
    if (seq !== app.loadSeq) return;
    view.reset(frame);
    fleet.clear();
    // The whole border in view, and any wall drawn outside it.
    const bounds = view.setWalls(shown);
    const border = entry && entry.bounds ? view.setBorder(entry.bounds) : null;
    view.fit(border ? border.extend(bounds) : bounds);
    for (const r of Object.values(app.robots)) robotChanged(r);
    const q = frame.query;
    const [objects, avoided, topo] = await Promise.all([
      fleetApi.get(base + '/objects' + q).catch(() => null),
      fleetApi.get(base + '/avoided' + q).catch(() => null),
      fleetApi.get(base + '/topology').catch(() => null),
    ]);
    if (seq !== app.loadSeq) return;
    if (objects) view.setObjects(objects);
    if (avoided) view.setAvoided(avoided);
    if (topo && (frame.name === 'map' || frame.usable)) view.setTopology(topo);
  } catch (e) {
    showFailure('Loading map ' + name, e);
  }
  updateControls();
}

// ---- robots ------------------------------------------------------------------------

function robotChanged(r) {
  app.robots[r.name] = r;
  const onMap = view.map !== null && app.mapName !== null && r.map === app.mapName;
  fleet.update(r, onMap);
  if (onMap && fleet.markers[r.name] && !fleet.trail(r.name).loaded && !fleet.trail(r.name).loading) loadTrail(r.name);
  robotRow(r);
  if (r.name === fleet.selected) updateControls();
}

async function loadTrail(name) {
  const t = fleet.trail(name);
  t.loading = true;
  const seq = app.loadSeq;
  const q = '?since=10m' + (view.frame.name === 'wgs84' ? '&crs=wgs84' : '');
  try {
    const fc = await fleetApi.get(apiPath`/api/robots/${name}/trajectory` + q);
    if (seq === app.loadSeq) fleet.setHistory(name, fc);
  } catch (e) {
    if (seq === app.loadSeq) t.loaded = true;  // shown live only
  }
  t.loading = false;
}

function robotRow(r) {
  const tbody = $('robots');
  let tr = tbody.querySelector('tr[data-robot="' + CSS.escape(r.name) + '"]');
  if (!tr) {
    tr = document.createElement('tr');
    tr.dataset.robot = r.name;
    for (let i = 0; i < 4; ++i) tr.appendChild(document.createElement('td'));
    tr.addEventListener('click', () => selectRobot(r.name));
    const after = Array.from(tbody.children).find((row) => row.dataset.robot > r.name);
    tbody.insertBefore(tr, after || null);
  }
  const c = tr.children;
  c[0].textContent = r.name;
  tr.classList.toggle('elsewhere', r.map !== app.mapName);
  tr.title = r.map !== app.mapName ? r.name + ' is on map ' + (r.map || '(none)') : '';
  c[1].innerHTML = '';
  const dot = document.createElement('i');
  dot.className = 'dot state-' + r.state;
  c[1].appendChild(dot);
  c[1].appendChild(document.createTextNode(r.state));
  c[2].textContent = fmt(r.x, 1) + ', ' + fmt(r.y, 1) + ', ' +
    (r.theta === null || r.theta === undefined ? '–' : (Math.round(r.theta * 180 / Math.PI) + 0) + '°');
  c[3].textContent = r.task ? '#' + r.task.id + ' ' + r.task.state : '';
  tr.dataset.state = r.state;
  tr.classList.toggle('selected', r.name === fleet.selected);
}

function selectRobot(name) {
  fleet.select(name);
  for (const tr of $('robots').children) tr.classList.toggle('selected', tr.dataset.robot === name);
  const r = app.robots[name];
  if (r && r.map === app.mapName && fleet.trails[name] && !fleet.trails[name].loaded) loadTrail(name);
  updateControls();
}

// ---- goals and poses by clicking the map ---------------------------------------------

function setMode(mode) {
  app.mode = mode;
  $('mode-goal').classList.toggle('active', mode === 'goal');
  $('mode-pose').classList.toggle('active', mode === 'pose');
  $('map').classList.toggle('pick', mode !== null);
}

function updateControls() {
  const name = fleet.selected;
  const r = name ? app.robots[name] : null;
  const here = r && r.map === app.mapName && (view.frame.name === 'map' || view.frame.usable);
  $('selected').textContent = name ? name + (r && r.map !== app.mapName ? ' (on ' + r.map + ')' : '') : 'No robot selected';
  $('mode-goal').disabled = !here || !isOperator();
  $('mode-pose').disabled = !here || !isOperator();
  $('goal-named-submit').disabled = !(r && isOperator());
  if (!here && app.mode) setMode(null);
}

async function onMapClick(latlng) {
  if (!app.mode || !fleet.selected) return;
  const p = view.frame.fromLatLng(latlng);
  if (!p) return;
  const mode = app.mode;
  const name = fleet.selected;
  setMode(null);  // one click, one request
  const x = Math.round(p.x * 1000) / 1000, y = Math.round(p.y * 1000) / 1000;
  if (mode === 'goal') {
    await sendGoal(name, { x: x, y: y });
  } else {
    const deg = $('pose-theta').value;
    const body = { x: x, y: y };
    if (deg !== '') body.theta = Number(deg) * Math.PI / 180;
    try {
      await fleetApi.post(apiPath`/api/robots/${name}/pose`, body);
      showMessage('Initial pose of ' + name + ': (' + fmt(x) + ', ' + fmt(y) + ')');
    } catch (e) {
      showFailure('Pose', e);
    }
  }
}

// body: {"x","y"}, {"tag"} or {"node"} (POST /api/robots/{name}/goal).
async function sendGoal(name, body) {
  try {
    const res = await fleetApi.post(apiPath`/api/robots/${name}/goal`, body);
    showMessage('Task #' + res.task + ': ' + name + ' to (' + fmt(res.goal[0]) + ', ' + fmt(res.goal[1]) + ')' +
      (res.path_length !== undefined && res.path_length !== null ? ', path ' + fmt(res.path_length, 1) + ' m' : ''));
    await refreshTasks();
  } catch (e) {
    showFailure('Goal', e);
  }
}

async function onNamedGoal(ev) {
  ev.preventDefault();
  const name = fleet.selected, target = $('goal-name').value.trim();
  if (!name || !target) return;
  await sendGoal(name, $('goal-kind').value === 'node' ? { node: target } : { tag: target });
}

// ---- tasks ----------------------------------------------------------------------------

async function refreshTasks() {
  try {
    const list = await fleetApi.get('/api/tasks?limit=' + TASKS_SHOWN);
    for (const t of list) taskChanged(t);
  } catch (e) {
    showFailure('Loading the tasks', e);
  }
}

function taskChanged(t) {
  app.tasks[t.id] = t;
  const tbody = $('tasks');
  let tr = tbody.querySelector('tr[data-task="' + t.id + '"]');
  if (!tr) {
    tr = document.createElement('tr');
    tr.dataset.task = String(t.id);
    for (let i = 0; i < 6; ++i) tr.appendChild(document.createElement('td'));
    tr.children[4].className = 'reason';
    const after = Array.from(tbody.children).find((row) => Number(row.dataset.task) < t.id);  // newest first
    tbody.insertBefore(tr, after || null);
    while (tbody.children.length > TASKS_SHOWN) tbody.removeChild(tbody.lastChild);
  }
  tr.dataset.state = t.state;
  tr.dataset.robot = t.robot;
  const c = tr.children;
  c[0].textContent = t.id;
  c[1].textContent = t.robot;
  c[2].textContent = t.state;
  c[3].textContent = t.goal ? fmt(t.goal[0], 1) + ', ' + fmt(t.goal[1], 1) : '';
  c[4].textContent = t.reason || '';
  c[4].title = t.reason || '';
  const open = OPEN_TASK_STATES.indexOf(t.state) >= 0;
  let button = c[5].querySelector('button');
  if (open && isOperator() && !button) {
    button = document.createElement('button');
    button.type = 'button';
    button.className = 'abort write-control';
    button.textContent = 'Abort';
    button.addEventListener('click', () => abortTask(t.id));
    c[5].appendChild(button);
  } else if (!open && button) {
    c[5].removeChild(button);
  }
}

async function abortTask(id) {
  const t = app.tasks[id];
  if (!t) return;
  try {
    await fleetApi.post(apiPath`/api/robots/${t.robot}/abort`, { reason: 'aborted from the console by ' + app.session.user });
    showMessage('Abort of task #' + id + ' (' + t.robot + ') sent');
    await refreshTasks();
  } catch (e) {
    showFailure('Abort', e);
  }
}

// ---- the live feed (GET /api/ws) ------------------------------------------------------

function connectFeed() {
  if (!app.session) return;
  const ws = new WebSocket((location.protocol === 'https:' ? 'wss://' : 'ws://') + location.host + '/api/ws');
  app.ws = ws;
  $('feed').textContent = 'connecting';
  ws.onopen = () => { $('feed').textContent = 'live'; $('feed').className = 'live'; };
  ws.onmessage = (ev) => {
    let msg;
    try { msg = JSON.parse(ev.data); } catch (e) { return; }
    if (msg.type === 'robots') for (const r of msg.robots || []) robotChanged(r);
    else if (msg.type === 'tasks') for (const t of msg.tasks || []) taskChanged(t);
  };
  ws.onclose = () => {
    if (app.ws !== ws) return;
    app.ws = null;
    $('feed').textContent = 'reconnecting';
    $('feed').className = '';
    // A closed feed may mean a lost session: ask before reconnecting.
    setTimeout(async () => {
      if (!app.session) return;
      try { await fleetApi.get('/api/session'); connectFeed(); } catch (e) {
        if (e instanceof ApiFailure && e.status === 401) sessionLost(); else setTimeout(connectFeed, 2000);
      }
    }, 1000);
  };
}

// ---- wiring -----------------------------------------------------------------------------

$('login-form').addEventListener('submit', onLoginSubmit);
$('logout').addEventListener('click', logout);
$('goal-named').addEventListener('submit', onNamedGoal);
$('map-select').addEventListener('change', (e) => showMap(e.target.value, false));
$('crs-wgs84').addEventListener('change', (e) => showMap(app.mapName, e.target.checked));
$('mode-goal').addEventListener('click', () => setMode(app.mode === 'goal' ? null : 'goal'));
$('mode-pose').addEventListener('click', () => setMode(app.mode === 'pose' ? null : 'pose'));
for (const name of ['walls', 'objects', 'avoided', 'topology', 'trails']) {
  $('layer-' + name).addEventListener('change', (e) => view.showLayer(name, e.target.checked));
}
document.addEventListener('keydown', (e) => { if (e.key === 'Escape') setMode(null); });

// For tests and the curious: the map, the fleet's states, and where a map-frame point is
// on screen (container pixels of #map).
window.fleetmapConsole = {
  get map() { return view.map; },
  get frame() { return view.frame.name; },
  // WGS 84 view: the map frame -> Web Mercator affine transform fitted to the walls (frames.js).
  get wgs84Fit() { return view.frame.fit ? { residual: view.frame.fit.residual, rotation: view.frame.fit.rotation } : null; },
  get robots() { return app.robots; },
  get markers() { return fleet.markers; },
  get trails() { return fleet.trails; },  // name -> {line: L.Polyline of runs, loaded}
  get tasks() { return app.tasks; },
  get session() { return app.session; },
  get lastError() { return app.lastError; },
  toContainerPoint(x, y) {
    const ll = view.frame.toLatLng(x, y);
    if (!ll || !view.map) return null;
    const p = view.map.latLngToContainerPoint(ll);
    return { x: p.x, y: p.y };
  },
};

boot();
