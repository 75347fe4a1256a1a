// The two frames the console draws in.
//
// "map": the map's own frame, x and y in metres, drawn in L.CRS.Simple with
// latlng = [y, x], so +x is right and +y is up as in the seed's figures.
//
// "wgs84": a georeferenced map drawn in L.CRS.EPSG3857 (no tiles: the console works
// offline). The server gives the layers in lon/lat (?crs=wgs84, through PROJ) and each
// robot's lonlat. What the server does not give is the way back (a click in lon/lat to
// the map-frame x, y a goal needs) or how a heading looks on screen: both come from an
// affine transform fitted to the walls' vertices, which the server sent in both frames
// in the same order. Affine, not a similarity: Web Mercator applies spherical formulas to
// ellipsoidal coordinates, so it is not quite conformal (about 0.3 % apart north-south
// and east-west at 47 degrees: 6 cm over the 60 m campus for a similarity); over a site
// that local stretch is linear, and the affine fit is exact to millimetres. The fit's
// worst residual is kept, and clicks are refused when it is poor.
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

// [u, v] = A [x, y] + t, least squares over point pairs; null when the points are
// too few or all on one line.
function fitAffine(from, to) {
  const n = Math.min(from.length, to.length);
  if (n < 3) return null;
  let mx = 0, my = 0, mu = 0, mv = 0;
  for (let i = 0; i < n; ++i) { mx += from[i][0]; my += from[i][1]; mu += to[i][0]; mv += to[i][1]; }
  mx /= n; my /= n; mu /= n; mv /= n;
  let sxx = 0, sxy = 0, syy = 0, sxu = 0, syu = 0, sxv = 0, syv = 0;
  for (let i = 0; i < n; ++i) {
    const x = from[i][0] - mx, y = from[i][1] - my, u = to[i][0] - mu, v = to[i][1] - mv;
    sxx += x * x; sxy += x * y; syy += y * y; sxu += x * u; syu += y * u; sxv += x * v; syv += y * v;
  }
  const det = sxx * syy - sxy * sxy;
  if (!(Math.abs(det) > 1e-9 * (sxx * syy + 1e-300))) return null;
  const a = (sxu * syy - syu * sxy) / det, b = (syu * sxx - sxu * sxy) / det;
  const c = (sxv * syy - syv * sxy) / det, d = (syv * sxx - sxv * sxy) / det;
  const t = { a: a, b: b, c: c, d: d, tx: mu - a * mx - b * my, ty: mv - c * mx - d * my };
  const scale = Math.sqrt(Math.abs(a * d - b * c));
  let worst = 0;
  for (let i = 0; i < n; ++i) {
    const p = applyAffine(t, from[i][0], from[i][1]);
    worst = Math.max(worst, Math.hypot(p[0] - to[i][0], p[1] - to[i][1]) / scale);
  }
  t.residual = worst;  // metres of the map frame
  t.rotation = Math.atan2(c, a);  // where the map's +x points on screen
  return t;
}

function applyAffine(t, x, y) { return [t.a * x + t.b * y + t.tx, t.c * x + t.d * y + t.ty]; }

function invertAffine(t, u, v) {
  const det = t.a * t.d - t.b * t.c, pu = u - t.tx, pv = v - t.ty;
  return [(t.d * pu - t.b * pv) / det, (t.a * pv - t.c * pu) / det];
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
  const fit = from.length === to.length ? fitAffine(from, to) : null;
  const usable = fit !== null && fit.residual < 0.25;
  return {
    name: 'wgs84',
    crs: proj,
    fit: fit,
    usable: usable,  // clicks and map-frame overlays need the fit
    toLatLng(x, y) {
      if (!fit) return null;
      const p = applyAffine(fit, x, y);
      return proj.unproject(L.point(p[0], p[1]));
    },
    fromLatLng(ll) {
      if (!usable) return null;
      const p = proj.project(ll), q = invertAffine(fit, p.x, p.y);
      return { x: q[0], y: q[1] };
    },
    // The heading's direction as the transform draws it (y up in both frames).
    screenHeading(theta) {
      if (!fit) return theta;
      const c = Math.cos(theta), s = Math.sin(theta);
      return Math.atan2(fit.c * c + fit.d * s, fit.a * c + fit.b * s);
    },
    robotLatLng(r) { return r.lonlat ? L.latLng(r.lonlat[1], r.lonlat[0]) : null; },
    query: '?crs=wgs84',
  };
}
