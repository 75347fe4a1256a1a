// The map: one Leaflet map in the current frame (frames.js) with the map's layers
// (walls, objects, avoided areas, topology) and the fleet's (trajectories, goals,
// robots). Switching frames rebuilds it: Leaflet cannot change a map's CRS.
'use strict';

// Tooltip content as text: Leaflet would take a string as HTML, and names, semantic
// strings and GIS attributes are data (an imported layer may hold anything).
function plainText(text) {
  const span = document.createElement('span');
  span.textContent = String(text);
  return span;
}

const SHAPE_COLOURS = { stairs: '#8250df', ramp: '#9a6700' };

function shapeColour(type) {
  const t = String(type).toLowerCase();
  if (t === '5' || t.indexOf('stair') >= 0) return SHAPE_COLOURS.stairs;
  if (t === '6' || t.indexOf('ramp') >= 0) return SHAPE_COLOURS.ramp;
  return '#24292f';
}

class MapView {
  constructor(elementId, onClick) {
    this.elementId = elementId;
    this.onClick = onClick;
    this.map = null;
    this.frame = mapFrame;
  }

  // A fresh Leaflet map in frame, with empty layer groups.
  reset(frame) {
    if (this.map) this.map.remove();
    this.frame = frame;
    this.map = L.map(this.elementId, {
      crs: frame.crs,
      minZoom: frame.name === 'map' ? -6 : 1,
      maxZoom: frame.name === 'map' ? 6 : 24,
      zoomSnap: 0.25,
      attributionControl: false,
    });
    this.layers = {};
    for (const name of ['walls', 'objects', 'avoided', 'topology', 'trails', 'goals', 'robots']) {
      this.layers[name] = L.layerGroup();
    }
    for (const name of ['walls', 'objects', 'avoided', 'topology', 'trails']) {
      const box = document.getElementById('layer-' + name);
      if (!box || box.checked) this.layers[name].addTo(this.map);
    }
    this.layers.goals.addTo(this.map);
    this.layers.robots.addTo(this.map);
    L.control.scale({ imperial: false }).addTo(this.map);
    this.map.on('click', (e) => this.onClick(e.latlng));
    return this.map;
  }

  showLayer(name, on) {
    if (!this.map) return;
    if (on) this.layers[name].addTo(this.map);
    else this.map.removeLayer(this.layers[name]);
  }

  fit(bounds) {
    if (bounds && bounds.isValid()) this.map.fitBounds(bounds, { padding: [10, 10] });
    else this.map.setView([0, 0], 0);
  }

  // GeoJSON of the walls: one Feature per obstacle, {"obstacle", "type", "h"}.
  setWalls(fc) {
    this.layers.walls.clearLayers();
    const layer = L.geoJSON(fc, {
      style: (f) => ({ className: 'layer-walls', color: shapeColour(f.properties && f.properties.type), weight: 2, fill: false }),
      onEachFeature: (f, l) => {
        const p = f.properties || {};
        l.bindTooltip(plainText('obstacle ' + p.obstacle + ' · ' + p.type +
          (p.h !== undefined && p.h !== null ? ' · h ' + p.h + ' m' : '')), { sticky: true });
      },
    });
    this.layers.walls.addLayer(layer);
    return layer.getBounds();
  }

  // The map's border (GET /api/maps "bounds"), map frame: where a goal may be (SPEC 3).
  setBorder(b) {
    const f = this.frame;
    const corners = [[b[0], b[1]], [b[2], b[1]], [b[2], b[3]], [b[0], b[3]]].map((c) => f.toLatLng(c[0], c[1]));
    if (corners.some((c) => !c)) return null;
    this.layers.walls.addLayer(L.polygon(corners, { color: '#8c959f', weight: 1, dashArray: '6 4', fill: false,
      interactive: false }));
    return L.latLngBounds(corners);
  }

  setObjects(fc) { this.setOverlay('objects', fc, { className: 'layer-objects', color: '#bc4c00', weight: 1.5, fillOpacity: 0.15 }); }
  setAvoided(fc) { this.setOverlay('avoided', fc, { className: 'layer-avoided', color: '#cf222e', weight: 1, dashArray: '4 3', fillOpacity: 0.2 }); }

  setOverlay(name, fc, style) {
    this.layers[name].clearLayers();
    this.layers[name].addLayer(L.geoJSON(fc, {
      style: () => style,
      pointToLayer: (f, ll) => L.circleMarker(ll, Object.assign({ radius: 4 }, style)),
      onEachFeature: (f, l) => {
        const p = f.properties || {};
        const label = p.name || p.label || p.id || p.kind || p.type;
        const what = p.tag || p.kind;
        if (label !== undefined) l.bindTooltip(plainText(label + (what && what !== label ? ' (' + what + ')' : '')), { sticky: true });
      },
    }));
  }

  // {"nodes": [{id, name, type, x, y}], "edges": [{from, to, type}]}, map frame.
  setTopology(topo) {
    const g = this.layers.topology;
    g.clearLayers();
    const at = {};
    for (const n of topo.nodes || []) at[n.id] = this.frame.toLatLng(n.x, n.y);
    for (const e of topo.edges || []) {
      if (at[e.from] && at[e.to]) {
        g.addLayer(L.polyline([at[e.from], at[e.to]], { color: '#0969da', weight: 1.5, opacity: 0.6, interactive: false }));
      }
    }
    for (const n of topo.nodes || []) {
      if (!at[n.id]) continue;
      g.addLayer(L.circleMarker(at[n.id], { radius: 4, color: '#0969da', weight: 1, fillOpacity: 0.8 })
        .bindTooltip(plainText((n.name || ('node ' + n.id)) + (n.type ? ' (' + n.type + ')' : ''))));
    }
  }
}
