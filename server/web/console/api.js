// The console's one way to the server: JSON over fetch, the session's CSRF token on
// every write (SPEC 4: POST/PUT/DELETE need X-CSRF-Token equal to the session's), and
// the API's error object turned into an exception the page can show.
'use strict';

// {"error": {"status", "code", "exit_code", "message"}} (docs/openapi.json), or what a
// broken reply leaves of it.
class ApiFailure extends Error {
  constructor(status, body) {
    const e = body && body.error ? body.error : {};
    super(e.message || ('HTTP ' + status));
    this.status = status;
    this.code = e.code || 'http_' + status;
    this.exitCode = e.exit_code;
    this.body = body;
  }
}

const fleetApi = {
  csrf: null,  // kept in memory only: never in storage, never in a cookie the page can read

  async request(method, path, body) {
    const headers = { 'Accept': 'application/json' };
    if (method !== 'GET' && method !== 'HEAD' && this.csrf) headers['X-CSRF-Token'] = this.csrf;
    const init = { method: method, headers: headers, credentials: 'same-origin', cache: 'no-store' };
    if (body !== undefined) {
      headers['Content-Type'] = 'application/json';
      init.body = JSON.stringify(body);
    }
    const res = await fetch(path, init);
    const text = await res.text();
    let data = null;
    if (text) {
      try { data = JSON.parse(text); } catch (e) { data = { error: { message: text.slice(0, 200) } }; }
    }
    if (!res.ok) throw new ApiFailure(res.status, data);
    return data;
  },

  get(path) { return this.request('GET', path); },
  post(path, body) { return this.request('POST', path, body === undefined ? {} : body); },
};

// Path segments of robot and map names are user data: always encoded.
function apiPath(strings, ...values) {
  let out = strings[0];
  values.forEach((v, i) => { out += encodeURIComponent(String(v)) + strings[i + 1]; });
  return out;
}
