// The fleet on the map: a marker per robot (an arrow rotated by its heading, coloured
// by its state as the legend says, its name beside it), its trajectory as a line and
// its goal as a small cross.
'use strict';

const ARROW_SVG = '<svg width="24" height="24" viewBox="0 0 24 24" aria-hidden="true">' +
  '<path d="M22 12 L3 3.5 L8 12 L3 20.5 Z"/></svg>';
const TRAIL_MAX_POINTS = 5000;  // ten minutes at the robots' 3 Hz (SPEC 1), with room
const TRAIL_GAP_MS = 10000;     // a silence this long cuts the line (poses come at 3 Hz)

// Drops the oldest points beyond TRAIL_MAX_POINTS, and runs left empty.
function trimRuns(runs) {
  let n = runs.reduce((sum, r) => sum + r.length, 0);
  while (n > TRAIL_MAX_POINTS && runs.length) {
    const drop = Math.min(runs[0].length, n - TRAIL_MAX_POINTS);
    runs[0].splice(0, drop);
    n -= drop;
    if (!runs[0].length && runs.length > 1) runs.shift();
    else if (!runs[0].length) break;
  }
}

class FleetView {
  constructor(view, onSelect) {
    this.view = view;
    this.onSelect = onSelect;
    this.markers = {};  // name -> L.Marker
    this.trails = {};   // name -> {line: L.Polyline, loaded: bool}
    this.goals = {};    // name -> L.CircleMarker
    this.selected = null;
  }

  // After MapView.reset: the old layers went with the old map.
  clear() { this.markers = {}; this.trails = {}; this.goals = {}; }

  // One robot state as the WebSocket and GET /api/robots give it; onMap is false for a
  // robot on another map (its marker, trail and goal are removed).
  update(r, onMap) {
    const frame = this.view.frame;
    const ll = onMap ? frame.robotLatLng(r) : null;
    let m = this.markers[r.name];
    if (!onMap) { this.remove(r.name); return; }  // its trail too: it belongs to another map
    if (!ll) {
      if (m) { this.view.layers.robots.removeLayer(m); delete this.markers[r.name]; }
      this.setGoal(r.name, null);
      return;
    }
    if (!m) {
      m = L.marker(ll, { icon: this.icon(r.name), keyboard: false, riseOnHover: true });
      m.on('click', () => this.onSelect(r.name));
      m.addTo(this.view.layers.robots);
      this.markers[r.name] = m;
    } else {
      m.setLatLng(ll);
    }
    const el = m.getElement();
    if (el) {
      const arrow = el.querySelector('.arrow');
      arrow.className = 'arrow state-' + r.state;
      // CSS turns clockwise, theta counter-clockwise: rotate by -theta.
      const theta = (r.theta === null || r.theta === undefined) ? 0 : frame.screenHeading(r.theta);
      arrow.style.transform = 'rotate(' + (-theta) + 'rad)';
      arrow.style.opacity = r.theta === null || r.theta === undefined ? '0.5' : '1';
      el.classList.toggle('selected', r.name === this.selected);
      el.title = r.name + ' · ' + r.state;
    }
    this.appendTrail(r.name, ll);
    this.setGoal(r.name, r.goal ? frame.toLatLng(r.goal[0], r.goal[1]) : null);
  }

  icon(name) {
    const label = document.createElement('span');
    label.className = 'label';
    label.textContent = name;
    return L.divIcon({
      className: 'robot-icon',
      html: '<div class="arrow">' + ARROW_SVG + '</div>' + label.outerHTML,
      iconSize: [24, 24],
      iconAnchor: [12, 12],
    });
  }

  remove(name) {
    if (!this.view.layers) return;  // no map drawn yet: nothing on it
    if (this.markers[name]) this.view.layers.robots.removeLayer(this.markers[name]);
    if (this.trails[name]) this.view.layers.trails.removeLayer(this.trails[name].line);
    delete this.markers[name];
    delete this.trails[name];
    this.setGoal(name, null);
  }

  // Signed out: nothing of the fleet stays on screen.
  removeAll() {
    for (const name of new Set(Object.keys(this.markers).concat(Object.keys(this.trails), Object.keys(this.goals)))) {
      this.remove(name);
    }
    this.selected = null;
  }

  select(name) {
    this.selected = name;
    for (const n of Object.keys(this.markers)) {
      const el = this.markers[n].getElement();
      if (el) el.classList.toggle('selected', n === name);
    }
  }

  trail(name) {
    if (!this.trails[name]) {
      const line = L.polyline([[]], { color: '#6e7781', weight: 2, opacity: 0.7, interactive: false });
      line.addTo(this.view.layers.trails);
      this.trails[name] = { line: line, loaded: false };
    }
    return this.trails[name];
  }

  // The line is a list of runs (L.Polyline's nested form): the live states extend the last.
  appendTrail(name, ll) {
    const t = this.trail(name);
    const runs = t.line.getLatLngs();
    if (!runs.length || !Array.isArray(runs[0])) runs.splice(0, runs.length, []);
    const run = runs[runs.length - 1];
    const last = run.length ? run[run.length - 1] : null;
    if (last && last.lat === ll.lat && last.lng === ll.lng) return;
    run.push(ll);
    trimRuns(runs);
    t.line.setLatLngs(runs);
  }

  // The recorded trajectory (GeoJSON points with t) goes before what the live feed
  // appended meanwhile; it is cut where the robot was silent (offline, or an earlier
  // robot of the same name), so that no line jumps across the map.
  setHistory(name, fc) {
    const t = this.trail(name);
    const points = (fc.features || []).filter((f) => f.geometry && f.geometry.type === 'Point');
    points.sort((a, b) => String((a.properties || {}).t).localeCompare(String((b.properties || {}).t)));
    const runs = [];
    let run = null, lastT = null;
    for (const f of points) {
      const when = Date.parse((f.properties || {}).t);
      if (!run || (isFinite(when) && isFinite(lastT) && when - lastT > TRAIL_GAP_MS)) runs.push(run = []);
      run.push(L.latLng(f.geometry.coordinates[1], f.geometry.coordinates[0]));
      lastT = when;
    }
    const live = t.line.getLatLngs();
    const liveRun = live.length && Array.isArray(live[0]) ? live[live.length - 1] : live;
    if (runs.length) runs[runs.length - 1].push(...liveRun);
    else runs.push(liveRun.slice());
    trimRuns(runs);
    t.line.setLatLngs(runs);
    t.loaded = true;
  }

  setGoal(name, ll) {
    const g = this.goals[name];
    if (!ll) {
      if (g) { this.view.layers.goals.removeLayer(g); delete this.goals[name]; }
      return;
    }
    if (g) { g.setLatLng(ll); return; }
    this.goals[name] = L.circleMarker(ll, { radius: 5, color: '#1f6feb', weight: 2, fill: false, dashArray: '2 2' })
      .bindTooltip(plainText('goal of ' + name)).addTo(this.view.layers.goals);
  }
}
