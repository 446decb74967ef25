// The JavaScript side of the binding (web/dt_web.cpp): copies arrays into the WebAssembly
// memory, calls one exported function, and reads its result buffers. Loaded after dt_wasm.js
// (emscripten's single-file output, which defines the factory DTModule).
"use strict";
var DT = (function () {
  var M = null;
  var api = {};
  function outI() {
    var p = M._dtw_out_i() >> 2, n = M._dtw_out_i_size();
    return M.HEAP32.slice(p, p + n);
  }
  function outD() {
    var p = M._dtw_out_d() >> 3, n = M._dtw_out_d_size();
    return M.HEAPF64.slice(p, p + n);
  }
  function error() { return M.UTF8ToString(M._dtw_error()); }
  // The sentence of the last call (what the figure shows, in words: its aria-live text).
  api.text = function () { return M.UTF8ToString(M._dtw_out_s()); };
  // Calls f(pointer, n) with the points xy (x0 y0 x1 y1 ...) copied into wasm memory.
  function withPoints(xy, f) {
    var n = xy.length / 2;
    var p = M._malloc(8 * Math.max(1, xy.length));
    M.HEAPF64.set(xy, p >> 3);
    try { return f(p, n); } finally { M._free(p); }
  }
  function check(r) {
    if (r < 0) throw new Error("dt: " + error());
    return r;
  }
  // Result of a walk/cavity query (layout of describe() in dt_web.cpp).
  function cavityReport(ints, d) {
    var r = {
      walk: ints[0], walkFinite: ints[1], cavity: ints[2], cavityFinite: ints[3],
      boundary: ints[4], ball: ints[5], ballFinite: ints[6], duplicate: ints[7] === 1,
      outside: ints[8] === 1, boundaryFinite: ints[9]
    };
    var o = 0;
    function take(k, each) {
      var a = [];
      for (var i = 0; i < k; i++) { a.push(Array.prototype.slice.call(d, o, o + each)); o += each; }
      return a;
    }
    r.walkFaces = take(r.walkFinite, 6);
    r.cavityFaces = take(r.cavityFinite, 6);
    r.boundaryEdges = take(r.boundaryFinite, 4);
    r.ballFaces = take(r.ballFinite, 6);
    r.p = [d[o], d[o + 1]];
    r.text = api.text();
    return r;
  }
  api.ready = (typeof DTModule === "function" ? DTModule() : Promise.reject(
      new Error("dt_wasm.js is not loaded"))).then(function (m) {
    M = m;
    // The enumerations the figures show (stage names, map kinds, sign names), from the C++.
    api.record = JSON.parse(M.UTF8ToString(M._dtw_record()));
    return api;
  });
  // DT(S) by the fast kernel: Int32Array of index triples (counter-clockwise).
  api.triangulate = function (xy, checkIt) {
    return withPoints(xy, function (p, n) {
      check(M._dtw_triangulate(p, n, checkIt ? 1 : 0));
      return outI();
    });
  };
  // DT(S) by the corrected listings, canonical triples (smallest index first), sorted.
  api.triangulateListings = function (xy) {
    return withPoints(xy, function (p, n) {
      check(M._dtw_triangulate_listings(p, n));
      return outI();
    });
  };
  // A scene (mode 0: DT(S) with ghost faces; 1: super-triangles `factor` times the box (10 if
  // not given), the points inserted by step()).
  api.sceneInit = function (xy, mode, factor) {
    return withPoints(xy, function (p, n) { return check(M._dtw_scene_init(p, n, mode, factor || 10)); });
  };
  // The scene the calls below work on (each figure of a page keeps its own).
  api.useScene = function (id) { M._dtw_scene_select(id); };
  api.sceneMesh = function () {
    var k = M._dtw_scene_mesh();
    return { count: k, coords: outD(), ids: outI() };
  };
  api.query = function (x, y) {
    check(M._dtw_scene_query(x, y));
    return cavityReport(outI(), outD());
  };
  // 2.5: one insertion; the report has nSearch (the kernel's own count) and index.
  api.step = function () {
    var left = check(M._dtw_scene_step());
    var ints = outI();
    var r = cavityReport(ints, outD());
    r.nSearch = ints[10];
    r.index = ints[11];
    r.left = left;
    return r;
  };
  api.flipPrepare = function () { return check(M._dtw_flip_prepare()); };
  api.flipStep = function () {
    var left = check(M._dtw_flip_step());
    return { left: left, edges: outD(), ids: outI(), text: api.text() };
  };
  api.orient = function (ax, ay, bx, by, cx, cy) {
    M._dtw_orient(ax, ay, bx, by, cx, cy);
    var o = outI();
    return { naive: o[0], exact: o[1], stage: o[2] };
  };
  api.incircle = function (ax, ay, bx, by, cx, cy, dx, dy) {
    M._dtw_incircle(ax, ay, bx, by, cx, cy, dx, dy);
    var o = outI();
    return { naive: o[0], exact: o[1], stage: o[2] };
  };
  // kind 0: O(m,b,c); 1: O(c,b,m); 2: InC(b,c,e,m). cells: Int32Array of (naive, exact,
  // stage) per cell; stages: the cells each stage decided (stage order); wrong: naive != exact.
  api.predicateMap = function (kind, x0, y0, step, n, b, c, e) {
    e = e || [0, 0];
    check(M._dtw_predicate_map(kind, x0, y0, step, n, b[0], b[1], c[0], c[1], e[0], e[1]));
    var o = outI(), k = 3 * n * n, s = api.record.stages.length;
    return { cells: o.subarray(0, k), stages: Array.prototype.slice.call(o, k, k + s), wrong: o[k + s] };
  };
  // Cell (i, j) of the same map: its signs and stage; api.text() says them in words.
  api.mapCell = function (kind, i, j, x0, y0, step, b, c, e) {
    e = e || [0, 0];
    check(M._dtw_map_cell(kind, i, j, x0, y0, step, b[0], b[1], c[0], c[1], e[0], e[1]));
    var o = outI();
    return { naive: o[0], exact: o[1], stage: o[2] };
  };
  api.hilbertOrder = function (xy, depth) {
    return withPoints(xy, function (p, n) {
      check(M._dtw_hilbert_order(p, n, depth));
      return outI();
    });
  };
  api.brioOrder = function (xy, seed, depth) {
    return withPoints(xy, function (p, n) {
      var rounds = check(M._dtw_brio_order(p, n, seed, depth || 0));
      var o = outI();
      return { order: o.slice(0, n), roundStarts: o.slice(n, n + rounds) };
    });
  };
  // Seconds to triangulate dt::uniformPoints(n, seed) in WebAssembly, and the triangle count.
  api.benchTriangulate = function (n, seed) {
    var s = M._dtw_bench_triangulate(n, seed);
    return { seconds: s, triangles: outI()[0] };
  };
  return api;
})();
