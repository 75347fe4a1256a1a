// The fleet on the map: a marker per robot (an arrow rotated by its heading, coloured
// by its state as the legend says, its name beside it), its trajectory as a line and
// its goal as a small cross.
'use strict';

const ARROW_SVG = '<svg width="24" height="24" viewBox="0 0 24 24" aria-hidden="true">' +
  '<path d="M22 12 L3 3.5 L8 12 L3 20.5 Z"/></svg>';
const TRAIL_MAX_POINTS = 5000;  // ten minutes at the robots' 3 Hz (SPEC 1), with room

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
    if (this.markers[name]) this.view.layers.robots.removeLayer(this.markers[name]);
    if (this.trails[name]) this.view.layers.trails.removeLayer(this.trails[name].line);
    delete this.markers[name];
    delete this.trails[name];
    this.setGoal(name, null);
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
      const line = L.polyline([], { color: '#6e7781', weight: 2, opacity: 0.7, interactive: false });
      line.addTo(this.view.layers.trails);
      this.trails[name] = { line: line, loaded: false };
    }
    return this.trails[name];
  }

  appendTrail(name, ll) {
    const t = this.trail(name);
    const pts = t.line.getLatLngs();
    const last = pts.length ? pts[pts.length - 1] : null;
    if (last && last.lat === ll.lat && last.lng === ll.lng) return;
    if (pts.length >= TRAIL_MAX_POINTS) pts.splice(0, pts.length - TRAIL_MAX_POINTS + 1);
    pts.push(ll);
    t.line.setLatLngs(pts);
  }

  // The recorded trajectory (GeoJSON points with t, in time order) goes before what
  // the live feed appended meanwhile.
  setHistory(name, fc) {
    const t = this.trail(name);
    const history = [];
    const points = (fc.features || []).filter((f) => f.geometry);
    points.sort((a, b) => String((a.properties || {}).t).localeCompare(String((b.properties || {}).t)));
    for (const f of points) {
      const g = f.geometry;
      if (g.type === 'Point') history.push(L.latLng(g.coordinates[1], g.coordinates[0]));
      else if (g.type === 'LineString' || g.type === 'MultiPoint') {
        for (const c of g.coordinates) history.push(L.latLng(c[1], c[0]));
      }
    }
    const live = t.line.getLatLngs();
    t.line.setLatLngs(history.concat(live).slice(-TRAIL_MAX_POINTS));
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
      .bindTooltip('goal of ' + name).addTo(this.view.layers.goals);
  }
}
