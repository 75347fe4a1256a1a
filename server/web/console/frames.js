// The two frames the console draws in.
//
// "map": the map's own frame, x and y in metres, drawn in L.CRS.Simple with
// latlng = [y, x], so +x is right and +y is up as in the seed's figures.
//
// "wgs84": a georeferenced map drawn in L.CRS.EPSG3857 (no tiles: the console works
// offline). The server gives the layers in lon/lat (?crs=wgs84, through PROJ) and each
// robot's lonlat. What the server does not give is the way back (a click in lon/lat to
// the map-frame x, y a goal needs) or the frame's rotation (a heading on screen): both
// come from a similarity transform fitted to the walls' vertices, which the server sent
// in both frames in the same order. Web Mercator is conformal, so over a site of a few
// hundred metres a similarity fits to centimetres; the fit's residual is kept, and
// clicks are refused when it is poor.
'use strict';

const mapFrame = {
  name: 'map',
  crs: L.CRS.Simple,
  toLatLng(x, y) { return L.latLng(y, x); },
  fromLatLng(ll) { return { x: ll.lng, y: ll.lat }; },
  screenHeading(theta) { return theta; },
  robotLatLng(r) { return (r.x === null || r.x === undefined) ? null : L.latLng(r.y, r.x); },
  query: '',
};

// z' = a z + b over complex numbers (a = scale * e^(i rotation)), least squares.
function fitSimilarity(from, to) {
  const n = Math.min(from.length, to.length);
  if (n < 2) return null;
  let zx = 0, zy = 0, wx = 0, wy = 0;
  for (let i = 0; i < n; ++i) { zx += from[i][0]; zy += from[i][1]; wx += to[i][0]; wy += to[i][1]; }
  zx /= n; zy /= n; wx /= n; wy /= n;
  let re = 0, im = 0, norm = 0;
  for (let i = 0; i < n; ++i) {
    const px = from[i][0] - zx, py = from[i][1] - zy, qx = to[i][0] - wx, qy = to[i][1] - wy;
    re += qx * px + qy * py;  // (q * conj(p)).re
    im += qy * px - qx * py;  // (q * conj(p)).im
    norm += px * px + py * py;
  }
  if (norm === 0) return null;
  const ar = re / norm, ai = im / norm;
  const t = { ar: ar, ai: ai, bx: wx - (ar * zx - ai * zy), by: wy - (ai * zx + ar * zy) };
  const scale = Math.hypot(ar, ai);
  let worst = 0;
  for (let i = 0; i < n; ++i) {
    const p = applySimilarity(t, from[i][0], from[i][1]);
    worst = Math.max(worst, Math.hypot(p[0] - to[i][0], p[1] - to[i][1]) / scale);
  }
  t.residual = worst;  // metres of the map frame
  t.rotation = Math.atan2(ai, ar);
  return t;
}

function applySimilarity(t, x, y) { return [t.ar * x - t.ai * y + t.bx, t.ai * x + t.ar * y + t.by]; }

function invertSimilarity(t, u, v) {
  const d = t.ar * t.ar + t.ai * t.ai, px = u - t.bx, py = v - t.by;
  return [(t.ar * px + t.ai * py) / d, (t.ar * py - t.ai * px) / d];
}

// Every vertex of a FeatureCollection, in order.
function vertices(fc) {
  const out = [];
  const walk = (c) => {
    if (typeof c[0] === 'number') out.push(c);
    else c.forEach(walk);
  };
  (fc.features || []).forEach((f) => { if (f.geometry && f.geometry.coordinates) walk(f.geometry.coordinates); });
  return out;
}

// The wgs84 frame for one map, from its walls in the map frame and in lon/lat.
function makeWgs84Frame(wallsMap, wallsLonLat) {
  const proj = L.CRS.EPSG3857;
  const from = vertices(wallsMap);
  const to = vertices(wallsLonLat).map((c) => { const p = proj.project(L.latLng(c[1], c[0])); return [p.x, p.y]; });
  const fit = from.length === to.length ? fitSimilarity(from, to) : null;
  const usable = fit !== null && fit.residual < 0.25;
  return {
    name: 'wgs84',
    crs: proj,
    fit: fit,
    usable: usable,  // clicks and map-frame overlays need the fit
    toLatLng(x, y) {
      if (!fit) return null;
      const p = applySimilarity(fit, x, y);
      return proj.unproject(L.point(p[0], p[1]));
    },
    fromLatLng(ll) {
      if (!usable) return null;
      const p = proj.project(ll), q = invertSimilarity(fit, p.x, p.y);
      return { x: q[0], y: q[1] };
    },
    screenHeading(theta) { return theta + (fit ? fit.rotation : 0); },
    robotLatLng(r) { return r.lonlat ? L.latLng(r.lonlat[1], r.lonlat[0]) : null; },
    query: '?crs=wgs84',
  };
}
