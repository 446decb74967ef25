// The live figures of the book (book/live.md). Each figure is an object with a small API (used
// by the reader's pointer and buttons, and by the browser test web/test.js): it asks the
// WebAssembly library (DT, web/dt.js) for every geometric answer and only draws. Colours come
// from DT_STYLE (generated from figures/ch2/style.gp), so they mean what they mean in the
// static figures.
"use strict";
var DTLive = (function () {
  var SVGNS = "http://www.w3.org/2000/svg";
  var S = DT_STYLE;
  var SERIES = S.C_SERIES.split(" ");

  function el(tag, attrs, parent) {
    var e = document.createElementNS(SVGNS, tag);
    for (var k in attrs) e.setAttribute(k, attrs[k]);
    if (parent) parent.appendChild(e);
    return e;
  }
  function html(tag, attrs, parent, text) {
    var e = document.createElement(tag);
    for (var k in attrs) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  }
  // Reproducible points (a small xorshift generator; the seed is shown nowhere, the points are
  // only an example: the library decides everything about them).
  function randomPoints(n, seed) {
    var s = (seed >>> 0) || 1, xy = new Float64Array(2 * n);
    function next() { s ^= s << 13; s >>>= 0; s ^= s >>> 17; s ^= s << 5; s >>>= 0; return s / 4294967296; }
    for (var i = 0; i < 2 * n; i++) xy[i] = 0.05 + 0.9 * next();
    return xy;
  }
  // A view: world box -> SVG pixels, y up.
  function View(x0, y0, x1, y1, w, h) {
    var sx = w / (x1 - x0), sy = h / (y1 - y0), s = Math.min(sx, sy);
    this.s = s;
    this.X = function (x) { return (x - x0) * s; };
    this.Y = function (y) { return h - (y - y0) * s; };
    this.inv = function (px, py) { return [x0 + px / s, y0 + (h - py) / s]; };
  }
  // Path data of triangles given as flat coordinates, 6 per triangle.
  function triPath(v, c, from, count) {
    var d = [];
    for (var t = 0; t < count; t++) {
      var o = from + 6 * t;
      d.push("M" + v.X(c[o]).toFixed(2) + "," + v.Y(c[o + 1]).toFixed(2) +
             "L" + v.X(c[o + 2]).toFixed(2) + "," + v.Y(c[o + 3]).toFixed(2) +
             "L" + v.X(c[o + 4]).toFixed(2) + "," + v.Y(c[o + 5]).toFixed(2) + "Z");
    }
    return d.join("");
  }
  function polygons(g, v, faces, cls, fill, stroke) {
    for (var i = 0; i < faces.length; i++) {
      var f = faces[i];
      el("polygon", {
        "class": cls, fill: fill, stroke: stroke || "none", "stroke-width": 1,
        points: v.X(f[0]) + "," + v.Y(f[1]) + " " + v.X(f[2]) + "," + v.Y(f[3]) + " " +
                v.X(f[4]) + "," + v.Y(f[5])
      }, g);
    }
  }
  function clear(g) { while (g.firstChild) g.removeChild(g.firstChild); }
  function frame(root, title, w, h) {
    root.classList.add("dt-live-figure");
    var head = html("div", { "class": "dt-live-head" }, root, title);
    var svg = el("svg", { width: w, height: h, viewBox: "0 0 " + w + " " + h, "class": "dt-live-svg" }, root);
    el("rect", { x: 0, y: 0, width: w, height: h, fill: "white" }, svg);
    var controls = html("div", { "class": "dt-live-controls" }, root);
    var info = html("div", { "class": "dt-live-info" }, root);
    return { head: head, svg: svg, controls: controls, info: info };
  }
  // Dispatches a synthetic pointer event at world point (x, y) of a figure (the test uses it).
  function pointerAt(fig, type, x, y) {
    var r = fig.svg.getBoundingClientRect();
    var ev = new PointerEvent(type, {
      bubbles: true, clientX: r.left + fig.view.X(x), clientY: r.top + fig.view.Y(y),
      pointerId: 1, isPrimary: true, buttons: type === "pointerup" ? 0 : 1
    });
    fig.svg.dispatchEvent(ev);
  }
  function eventWorld(fig, ev) {
    var r = fig.svg.getBoundingClientRect();
    return fig.view.inv(ev.clientX - r.left, ev.clientY - r.top);
  }

  // ---- 2.1 / 2.4: the cavity, its boundary and the ball of a point one drags ----------------
  function Cavity(root, opts) {
    opts = opts || {};
    var W = opts.width || 560, H = opts.height || 560;
    var f = frame(root, "Figures 2.1 and 2.4, live: drag pₙ₊₁", W, H);
    var self = this;
    this.svg = f.svg;
    var gMesh = el("g", {}, f.svg), gCav = el("g", {}, f.svg), gBall = el("g", {}, f.svg),
        gBnd = el("g", {}, f.svg), gPts = el("g", {}, f.svg), gP = el("g", {}, f.svg);
    var sizes = opts.sizes || [15, 100, 1000, 10000];
    var sel = html("select", { "class": "dt-n" }, f.controls);
    sizes.forEach(function (n) { html("option", { value: n }, sel, "n = " + n); });
    var show = html("select", { "class": "dt-show" }, f.controls);
    html("option", { value: "cavity" }, show, "cavity 𝒞 and its boundary ∂𝒞");
    html("option", { value: "ball" }, show, "ball 𝓑 (the new triangles)");
    html("option", { value: "both" }, show, "both");
    show.value = "both";
    this.report = null;
    this.setPoints = function (xy) {
      self.xy = xy;
      DT.sceneInit(xy, 0);
      var m = DT.sceneMesh();
      var x0 = 1 / 0, y0 = 1 / 0, x1 = -1 / 0, y1 = -1 / 0;
      for (var i = 0; i < xy.length; i += 2) {
        x0 = Math.min(x0, xy[i]); x1 = Math.max(x1, xy[i]);
        y0 = Math.min(y0, xy[i + 1]); y1 = Math.max(y1, xy[i + 1]);
      }
      var mx = 0.04 * (x1 - x0), my = 0.04 * (y1 - y0);
      self.view = new View(x0 - mx, y0 - my, x1 + mx, y1 + my, W, H);
      clear(gMesh); clear(gPts);
      el("path", { d: triPath(self.view, m.coords, 0, m.count), fill: "none", stroke: S.C_TRI,
                   "stroke-width": xy.length > 2000 ? 0.4 : 1, "class": "mesh" }, gMesh);
      if (xy.length <= 2000) {
        for (var k = 0; k < xy.length; k += 2)
          el("circle", { cx: self.view.X(xy[k]), cy: self.view.Y(xy[k + 1]), r: 3, fill: S.C_POINT }, gPts);
      }
      self.meshTriangles = m.count;
      self.moveTo(x0 + 0.43 * (x1 - x0), y0 + 0.52 * (y1 - y0));
    };
    // Places p at (x, y): the library walks to it and collects 𝒞, ∂𝒞 and 𝓑; the figure draws them.
    this.moveTo = function (x, y) {
      var r = DT.query(x, y), v = self.view, mode = show.value;
      clear(gCav); clear(gBall); clear(gBnd); clear(gP);
      if (mode !== "ball") polygons(gCav, v, r.cavityFaces, "cavity", S.C_CAVITY, S.C_CAVITY_EDGE);
      if (mode !== "cavity")
        polygons(gBall, v, r.ballFaces, "ball", mode === "ball" ? S.C_BALL : "none", S.C_BALL_EDGE);
      r.boundaryEdges.forEach(function (e) {
        el("line", { "class": "boundary", x1: v.X(e[0]), y1: v.Y(e[1]), x2: v.X(e[2]), y2: v.Y(e[3]),
                     stroke: mode === "ball" ? S.C_BALL_EDGE : S.C_CAVITY_EDGE, "stroke-width": 3 }, gBnd);
      });
      el("circle", { cx: v.X(x), cy: v.Y(y), r: 6, fill: S.C_NEW, "class": "p" }, gP);
      self.report = r;
      f.info.textContent = "|𝒞| = " + r.cavityFinite + "   |∂𝒞| = " + r.boundaryFinite +
        "   |𝓑| = " + r.ballFinite + "   (walk: " + r.walk + " faces" +
        (r.outside ? "; p outside the hull: ghost faces not drawn" : "") +
        (r.duplicate ? "; p is a vertex: no cavity" : "") + ")";
      return r;
    };
    var dragging = false;
    f.svg.addEventListener("pointerdown", function (ev) {
      dragging = true;
      var w = eventWorld(self, ev);
      self.moveTo(w[0], w[1]);
    });
    f.svg.addEventListener("pointermove", function (ev) {
      if (!dragging) return;
      var t0 = performance.now();
      var w = eventWorld(self, ev);
      self.moveTo(w[0], w[1]);
      f.svg.getBBox();  // forces the layout of what changed (part of the redraw)
      self.lastMoveMs = performance.now() - t0;
    });
    window.addEventListener("pointerup", function () { dragging = false; });
    this.setSize = function (n) { sel.value = n; self.setPoints(randomPoints(n, 2024)); };
    sel.addEventListener("change", function () { self.setSize(+sel.value); });
    show.addEventListener("change", function () { if (self.report) self.moveTo(self.report.p[0], self.report.p[1]); });
    this.setShow = function (m) { show.value = m; self.moveTo(self.report.p[0], self.report.p[1]); };
    this.pointer = function (type, x, y) { pointerAt(self, type, x, y); };
    this.counts = function () {
      return { cavity: f.svg.querySelectorAll(".cavity").length, ball: f.svg.querySelectorAll(".ball").length,
               boundary: f.svg.querySelectorAll(".boundary").length };
    };
    this.setSize(sizes[0]);
  }

  // ---- 2.5: Bowyer-Watson step by step, from the super-triangles, with the walk ------------
  function BowyerWatson(root, opts) {
    opts = opts || {};
    var W = opts.width || 560, H = opts.height || 560;
    var f = frame(root, "Figure 2.5, live: Bowyer-Watson one insertion at a time", W, H);
    var self = this;
    this.svg = f.svg;
    // The faces of the walk and of the cavity (before the insertion) under the new mesh.
    var gWalk = el("g", {}, f.svg), gCav = el("g", {}, f.svg), gMesh = el("g", {}, f.svg),
        gPts = el("g", {}, f.svg);
    var btn = html("button", { "class": "dt-step" }, f.controls, "insert the next point");
    var reset = html("button", { "class": "dt-reset" }, f.controls, "start again");
    this.nSearchTotal = 0;
    this.steps = 0;
    function drawMesh() {
      var m = DT.sceneMesh();
      clear(gMesh);
      el("path", { d: triPath(self.view, m.coords, 0, m.count), fill: "none", stroke: S.C_TRI,
                   "stroke-width": 1, "class": "mesh" }, gMesh);
      self.meshTriangles = m.count;
    }
    this.start = function (xy) {
      self.xy = xy || randomPoints(opts.n || 20, 7);
      DT.sceneInit(self.xy, 1);
      // The super-triangles reach 10 times beyond the points: the view shows a part of them.
      self.view = new View(-0.6, -0.6, 1.6, 1.6, W, H);
      self.nSearchTotal = 0;
      self.steps = 0;
      self.left = self.xy.length / 2;
      clear(gWalk); clear(gCav); clear(gPts);
      drawMesh();
      // The points still to insert, hollow as in the static Figure 2.5; each is filled when
      // inserted (the super-triangles' corners lie outside the view: only their diagonal shows).
      for (var k = 0; k < self.xy.length; k += 2)
        el("circle", { cx: self.view.X(self.xy[k]), cy: self.view.Y(self.xy[k + 1]), r: 3,
                       fill: "white", stroke: S.C_POINT, "stroke-width": 1, "class": "pending" }, gPts);
      f.info.textContent = "DT_0: the two super-triangles (their diagonal crosses the view); " +
        self.left + " points to insert";
    };
    // Inserts the next point: draws the faces its walk visited and its cavity, then the new mesh.
    this.step = function () {
      if (self.left === 0) return null;
      var r = DT.step(), v = self.view;
      clear(gWalk); clear(gCav);
      polygons(gWalk, v, r.walkFaces, "walk", S.C_NEIGH, S.C_NEIGH_EDGE);
      polygons(gCav, v, r.cavityFaces, "cavity", S.C_CAVITY, S.C_CAVITY_EDGE);
      drawMesh();
      el("circle", { cx: v.X(r.p[0]), cy: v.Y(r.p[1]), r: 3, fill: S.C_POINT }, gPts);
      clear(self.marker || (self.marker = el("g", {}, f.svg)));
      el("circle", { cx: v.X(r.p[0]), cy: v.Y(r.p[1]), r: 6, fill: S.C_NEW }, self.marker);
      self.nSearchTotal += r.nSearch;
      self.steps++;
      self.left = r.left;
      self.report = r;
      f.info.textContent = "point " + self.steps + ": N_search = " + r.nSearch + " faces walked, |𝒞| = " +
        r.cavityFinite + "; N_search summed: " + self.nSearchTotal + "; " + r.left + " left";
      return r;
    };
    btn.addEventListener("click", function () { self.step(); });
    reset.addEventListener("click", function () { self.start(self.xy); });
    this.counts = function () {
      return { walk: f.svg.querySelectorAll(".walk").length, cavity: f.svg.querySelectorAll(".cavity").length };
    };
    this.click = function () { btn.dispatchEvent(new MouseEvent("click", { bubbles: true })); };
    this.start();
  }

  // ---- 2.7 / 2.8: the predicate maps, naive against exact, with zoom --------------------------
  function PredicateMap(root, opts) {
    opts = opts || {};
    var N = opts.n || 256, PX = opts.pixel || 2;
    var f = frame(root, "Figures 2.7 and 2.8, live: orient2d near a degenerate line", N * PX, N * PX);
    var self = this;
    this.svg = f.svg;
    f.svg.style.display = "none";
    var canvas = html("canvas", { width: N * PX, height: N * PX, "class": "dt-map" });
    root.insertBefore(canvas, f.controls);
    var what = html("select", { "class": "dt-what" }, f.controls);
    [["naive", "naive double sign"], ["exact", "exact sign (the kernel's)"],
     ["stage", "stage that decided it"], ["diff", "where naive is wrong"]].forEach(function (o) {
      html("option", { value: o[0] }, what, o[1]);
    });
    var kind = html("select", { "class": "dt-kind" }, f.controls);
    [["0", "O(a,b,c), Fig. 2.7 (a)"], ["1", "O(c,b,a), Fig. 2.7 (b)"], ["2", "InC(a,b,c,d)"]].forEach(function (o) {
      html("option", { value: o[0] }, kind, o[1]);
    });
    var zin = html("button", { "class": "dt-zin" }, f.controls, "zoom in");
    var zout = html("button", { "class": "dt-zout" }, f.controls, "zoom out");
    // Figure 2.7's configuration: b(12,12), c(24,24), a(1/2 + i eps, 1/2 + j eps), eps = 2^-53;
    // for incircle, a(1/2,-47/2), b(49/2,-47/2), c(49/2,1/2) and d moving (robustness.h).
    var EPS = Math.pow(2, -53);
    this.step = EPS;
    this.zoomLevel = 0;
    this.draw = function () {
      // Zooming keeps the corner (1/2, 1/2) of Figure 2.7 at cell (0, 0); below one ulp per
      // cell (zoom > 0) neighbouring cells round to the same point.
      var k = +kind.value, st = self.step, x0 = 0.5, y0 = 0.5;
      var cells = k === 2 ? DT.predicateMap(2, x0, y0, st, N, [0.5, -23.5], [24.5, -23.5], [24.5, 0.5])
                          : DT.predicateMap(k, x0, y0, st, N, [12, 12], [24, 24]);
      self.cells = cells;
      var ctx = canvas.getContext("2d"), mode = what.value, wrong = 0;
      var sign = { "-1": S.C_MINUS, "0": S.C_ZERO, "1": S.C_PLUS };
      for (var j = 0; j < N; j++)
        for (var i = 0; i < N; i++) {
          var o = 3 * (j * N + i), c;
          if (cells[o] !== cells[o + 1]) wrong++;
          if (mode === "naive") c = sign[cells[o]];
          else if (mode === "exact") c = sign[cells[o + 1]];
          else if (mode === "stage") c = SERIES[cells[o + 2] % SERIES.length];
          else c = cells[o] !== cells[o + 1] ? S.C_CONFLICT : "#ffffff";
          ctx.fillStyle = c;
          ctx.fillRect(i * PX, (N - 1 - j) * PX, PX, PX);
        }
      self.wrongCells = wrong;
      var stages = [0, 0, 0, 0, 0];
      for (var t = 2; t < cells.length; t += 3) stages[cells[t]]++;
      self.stages = stages;
      f.info.textContent = "cell = " + (st / EPS) + " × 2⁻⁵³; naive sign wrong in " + wrong + " of " +
        N * N + " cells. Decided by: ";
      [[0, "filter"], [4, "extended-exponent filter"], [2, "exact doubles"], [3, "128/256-bit integers"],
       [1, "GMP"]].forEach(function (p) {
        html("span", { "class": "dt-swatch", style: "background:" + SERIES[p[0]] }, f.info, "\u00a0\u00a0");
        f.info.appendChild(document.createTextNode(" " + p[1] + " " + stages[p[0]] + "  "));
      });
      return self;
    };
    this.zoom = function (d) {
      self.zoomLevel += d;
      self.step = EPS * Math.pow(2, -self.zoomLevel);
      return self.draw();
    };
    this.set = function (m, k) { what.value = m; if (k !== undefined) kind.value = String(k); return self.draw(); };
    what.addEventListener("change", function () { self.draw(); });
    kind.addEventListener("change", function () { self.draw(); });
    zin.addEventListener("click", function () { self.zoom(1); });
    zout.addEventListener("click", function () { self.zoom(-1); });
    this.canvas = canvas;
    this.draw();
  }

  // ---- 2.11 / 2.12: the Hilbert order with its depth, and BRIO rounds ----------------------
  function Hilbert(root, opts) {
    opts = opts || {};
    var W = opts.width || 560, H = opts.height || 560;
    var f = frame(root, "Figures 2.11 and 2.12, live: Hilbert depth and BRIO rounds", W, H);
    var self = this;
    this.svg = f.svg;
    var g = el("g", {}, f.svg);
    var depth = html("input", { type: "range", min: 1, max: 10, value: 3, "class": "dt-depth" }, f.controls);
    var mode = html("select", { "class": "dt-mode" }, f.controls);
    html("option", { value: "hilbert" }, mode, "Hilbert order");
    html("option", { value: "brio" }, mode, "BRIO rounds");
    var round = html("input", { type: "range", min: 1, max: 1, value: 1, "class": "dt-round" }, f.controls);
    this.xy = randomPoints(opts.n || 400, 99);
    this.view = new View(0, 0, 1, 1, W, H);
    this.draw = function () {
      var v = self.view, xy = self.xy, n = xy.length / 2, d = +depth.value;
      clear(g);
      var order, starts = [0], last = n;
      if (mode.value === "hilbert") {
        order = DT.hilbertOrder(xy, d);
      } else {
        var b = DT.brioOrder(xy, 1, d);
        order = b.order;
        starts = Array.prototype.slice.call(b.roundStarts);
        round.max = starts.length;
        if (+round.value > starts.length) round.value = starts.length;
        last = +round.value < starts.length ? starts[+round.value] : n;
      }
      self.order = order;
      self.roundStarts = starts;
      for (var r = 0; r < starts.length; r++) {
        var from = starts[r], to = Math.min(r + 1 < starts.length ? starts[r + 1] : n, last);
        if (from >= to) break;
        var pts = [];
        for (var k = from; k < to; k++) pts.push(v.X(xy[2 * order[k]]) + "," + v.Y(xy[2 * order[k] + 1]));
        el("polyline", { points: pts.join(" "), fill: "none", stroke: SERIES[r % SERIES.length],
                         "stroke-width": 1.5, "class": "curve" }, g);
        for (k = from; k < to; k++)
          el("circle", { cx: v.X(xy[2 * order[k]]), cy: v.Y(xy[2 * order[k] + 1]), r: 2.5,
                         fill: SERIES[r % SERIES.length], "class": "pt" }, g);
      }
      self.drawn = last;
      f.info.textContent = mode.value === "hilbert"
        ? "Hilbert order of " + n + " points on the curve of depth " + d + " (4^" + d + " cells)"
        : "BRIO: " + starts.length + " rounds (sizes " + starts.map(function (s, i) {
            return (i + 1 < starts.length ? starts[i + 1] : n) - s; }).join(", ") +
          "), each in Hilbert order of depth " + d + "; rounds 1.." + round.value + " drawn";
      return self;
    };
    this.set = function (m, d, r) {
      mode.value = m; depth.value = d; if (r !== undefined) round.value = r; return self.draw();
    };
    [depth, mode, round].forEach(function (c) { c.addEventListener("input", self.draw); c.addEventListener("change", self.draw); });
    this.draw();
  }

  // ---- 2.3.6: recovering DT(S) from DT(S0 ∪ S), one flip at a time --------------------------
  function Flips(root, opts) {
    opts = opts || {};
    var W = opts.width || 560, H = opts.height || 560;
    var f = frame(root, "Section 2.3.6, live: the recovery flips, one at a time", W, H);
    var self = this;
    this.svg = f.svg;
    var gMesh = el("g", {}, f.svg), gFlip = el("g", {}, f.svg), gPts = el("g", {}, f.svg);
    var btn = html("button", { "class": "dt-flip" }, f.controls, "next flip");
    var reset = html("button", { "class": "dt-reset" }, f.controls, "start again");
    function drawMesh() {
      var m = DT.sceneMesh(), d = [], dSuper = [];
      for (var t = 0; t < m.count; t++) {
        var sup = m.ids[3 * t] < 0 || m.ids[3 * t + 1] < 0 || m.ids[3 * t + 2] < 0;
        if (sup && self.finished) continue;  // the end: DT(S) alone
        (sup ? dSuper : d).push(triPath(self.view, m.coords, 6 * t, 1));
      }
      clear(gMesh);
      el("path", { d: dSuper.join(""), fill: "none", stroke: S.C_SUPER, "stroke-width": 0.8,
                   "stroke-dasharray": "4 3", "class": "super" }, gMesh);
      el("path", { d: d.join(""), fill: "none", stroke: S.C_TRI, "stroke-width": 1, "class": "mesh" }, gMesh);
      self.meshTriangles = m.count;
    }
    this.start = function (xy) {
      self.xy = xy || randomPoints(opts.n || 25, 5);
      // Super-triangles 1.25 times the box, as the static frames: small enough to need flips.
      DT.sceneInit(self.xy, 1, 1.25);
      for (var left = self.xy.length / 2; left > 0;) left = DT.step().left;
      self.total = DT.flipPrepare();
      self.done = 0;
      self.finished = false;
      self.view = new View(-0.7, -0.7, 1.7, 1.7, W, H);
      clear(gFlip); clear(gPts);
      drawMesh();
      for (var k = 0; k < self.xy.length; k += 2)
        el("circle", { cx: self.view.X(self.xy[k]), cy: self.view.Y(self.xy[k + 1]), r: 3, fill: S.C_POINT }, gPts);
      f.info.textContent = "DT(S0 ∪ S): " + self.total + " flips to recover DT(S)";
    };
    this.step = function () {
      if (self.finished) return null;
      var r = DT.flipStep(), v = self.view, e = r.edges;
      clear(gFlip);
      if (e.length !== 8) self.finished = true;
      drawMesh();
      if (e.length === 8) {
        self.done++;
        el("line", { x1: v.X(e[0]), y1: v.Y(e[1]), x2: v.X(e[2]), y2: v.Y(e[3]), stroke: S.C_CONFLICT,
                     "stroke-width": 3, "stroke-dasharray": "6 4", "class": "old" }, gFlip);
        el("line", { x1: v.X(e[4]), y1: v.Y(e[5]), x2: v.X(e[6]), y2: v.Y(e[7]), stroke: S.C_BALL_EDGE,
                     "stroke-width": 3, "class": "new" }, gFlip);
        f.info.textContent = "flip " + self.done + " of " + self.total + ": edge p" + r.ids[0] + " p" +
          r.ids[1] + " becomes p" + r.ids[2] + " p" + r.ids[3] + " (negative numbers: super vertices)";
      } else {
        f.info.textContent = "all " + self.total + " flips done: removing the faces that touch a super " +
          "vertex leaves DT(S), the same as recoverDelaunay's (checked by the library)";
      }
      return r;
    };
    btn.addEventListener("click", function () { self.step(); });
    reset.addEventListener("click", function () { self.start(self.xy); });
    this.click = function () { btn.dispatchEvent(new MouseEvent("click", { bubbles: true })); };
    this.start();
  }

  var kinds = { cavity: Cavity, bowyer: BowyerWatson, predicates: PredicateMap, hilbert: Hilbert, flips: Flips };
  // Builds the figure named by data-figure in every .dt-live element of the page.
  function mountAll() {
    var figs = [];
    document.querySelectorAll(".dt-live").forEach(function (node) {
      var K = kinds[node.getAttribute("data-figure")];
      if (K) figs.push(node.dtFigure = new K(node));
    });
    return figs;
  }
  return { Cavity: Cavity, BowyerWatson: BowyerWatson, PredicateMap: PredicateMap, Hilbert: Hilbert,
           Flips: Flips, mountAll: mountAll, randomPoints: randomPoints };
})();
