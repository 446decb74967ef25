// The live figures of the book (book/live.md). Each figure is an object with a small API (used
// by the reader's pointer, keys and buttons, and by the browser test web/test.js): it asks the
// WebAssembly library (DT, web/dt.js) for every geometric answer, every name it shows (the
// record of dtw_record: stage names, map kinds, signs) and the sentence that says what it shows
// (its aria-live line), and only draws. Colours come from DT_STYLE (generated from
// figures/ch2/style.gp), so they mean what they mean in the static figures.
"use strict";
var DTLive = (function () {
  var SVGNS = "http://www.w3.org/2000/svg";
  var S = DT_STYLE;
  var SERIES = S.C_SERIES.split(" ");
  var uid = 0;

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
  // A control with its visible label (a <label> around it gives it its accessible name).
  function labelled(parent, text, tag, attrs) {
    var l = html("label", { "class": "dt-label" }, parent, text + " ");
    return html(tag, attrs, l);
  }
  // Reproducible points (a small xorshift generator; the seed is shown nowhere, the points are
  // only an example: the library decides everything about them).
  function randomPoints(n, seed) {
    var s = (seed >>> 0) || 1, xy = new Float64Array(2 * n);
    function next() { s ^= s << 13; s >>>= 0; s ^= s >>> 17; s ^= s << 5; s >>>= 0; return s / 4294967296; }
    for (var i = 0; i < 2 * n; i++) xy[i] = 0.05 + 0.9 * next();
    return xy;
  }
  // A view: world box -> SVG user units (the viewBox), y up.
  function View(x0, y0, x1, y1, w, h) {
    var sx = w / (x1 - x0), sy = h / (y1 - y0), s = Math.min(sx, sy);
    this.s = s;
    this.box = [x0, y0, x1, y1];
    this.X = function (x) { return (x - x0) * s; };
    this.Y = function (y) { return h - (y - y0) * s; };
    this.inv = function (px, py) { return [x0 + px / s, y0 + (h - py) / s]; };
  }
  // The view of a box with a margin of 4 % on each side.
  function boxView(xy, w, h) {
    var x0 = 1 / 0, y0 = 1 / 0, x1 = -1 / 0, y1 = -1 / 0;
    for (var i = 0; i < xy.length; i += 2) {
      x0 = Math.min(x0, xy[i]); x1 = Math.max(x1, xy[i]);
      y0 = Math.min(y0, xy[i + 1]); y1 = Math.max(y1, xy[i + 1]);
    }
    var mx = 0.04 * (x1 - x0), my = 0.04 * (y1 - y0);
    return new View(x0 - mx, y0 - my, x1 + mx, y1 + my, w, h);
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

  // A legend: one entry per colour the figure uses, each a small drawing of what the colour
  // marks (a fill, a line, a dashed line, a dot) and its meaning in words.
  function legend(parent, items) {
    var ul = html("ul", { "class": "dt-legend" }, parent);
    items.forEach(function (it) {
      var li = html("li", {}, ul);
      if (it.canvas) li.appendChild(it.canvas);
      else {
        var sw = el("svg", { width: 22, height: 14, viewBox: "0 0 22 14", "aria-hidden": "true",
                             focusable: "false", "class": "dt-swatch" }, li);
        if (it.fill) el("rect", { x: 1, y: 1, width: 20, height: 12, fill: it.fill, stroke: it.stroke || "none" }, sw);
        else if (it.dot) el("circle", { cx: 11, cy: 7, r: it.r || 4, fill: it.dot, stroke: it.stroke || "none" }, sw);
        else el("line", { x1: 1, y1: 7, x2: 21, y2: 7, stroke: it.stroke, "stroke-width": it.width || 2,
                          "stroke-dasharray": it.dash || "none" }, sw);
      }
      var t = html("span", { "class": "dt-legend-text" }, li, it.text);
      if (it.key) t.setAttribute("data-key", it.key);
    });
    return ul;
  }

  // The frame every figure shares: a heading, the drawing (focusable, with a role, a name and
  // the keys it takes), the controls, a legend and the aria-live line that says in words what
  // the drawing shows. The fallback sentence the page put in root (for a reader without
  // JavaScript) goes: the figure has loaded.
  function frame(root, title, w, h, keys) {
    clear(root);
    root.classList.add("dt-live-figure");
    var id = "dt-live-" + (++uid);
    var head = html("div", { "class": "dt-live-head", id: id + "-head" }, root, title);
    var keyLine = html("div", { "class": "dt-live-keys", id: id + "-keys" }, root, "Keys, once the drawing has the focus: " + keys);
    var svg = el("svg", { width: w, height: h, viewBox: "0 0 " + w + " " + h, "class": "dt-live-svg",
                          tabindex: 0, role: "application", "aria-label": title,
                          "aria-describedby": id + "-keys " + id + "-info" }, root);
    el("rect", { x: 0, y: 0, width: w, height: h, fill: "white" }, svg);
    var controls = html("div", { "class": "dt-live-controls" }, root);
    var legendBox = html("div", { "class": "dt-live-legend" }, root);
    var info = html("div", { "class": "dt-live-info", id: id + "-info", "aria-live": "polite", role: "status" }, root);
    return { head: head, svg: svg, controls: controls, legend: legendBox, info: info, keys: keyLine, id: id };
  }
  // Keys on a focusable drawing: arrows call move(dx, dy, big) with dx, dy in {-1, 0, 1} (y up),
  // Enter and Space call step(); other keys go to more(key) when given.
  function keyboard(node, move, step, more) {
    node.addEventListener("keydown", function (ev) {
      var d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] }[ev.key];
      if (d && move) move(d[0], d[1], ev.shiftKey);
      else if ((ev.key === "Enter" || ev.key === " ") && step) step();
      else if (!(more && more(ev.key))) return;
      ev.preventDefault();
    });
  }
  // The world point under a pointer event: client coordinates through the inverse of the
  // drawing's own screen transform, so a figure scaled down to a phone's width maps right.
  function eventWorld(fig, ev) {
    var pt = fig.svg.createSVGPoint();
    pt.x = ev.clientX;
    pt.y = ev.clientY;
    var q = pt.matrixTransform(fig.svg.getScreenCTM().inverse());
    return fig.view.inv(q.x, q.y);
  }
  // Dispatches a synthetic pointer event at the client point that shows world point (x, y), found
  // from the drawing's box on screen (the test uses it; not the figure's own mapping).
  function pointerAt(fig, type, x, y) {
    var r = fig.svg.getBoundingClientRect(), vb = fig.svg.viewBox.baseVal;
    var cx = r.left + fig.view.X(x) * r.width / vb.width, cy = r.top + fig.view.Y(y) * r.height / vb.height;
    fig.svg.dispatchEvent(new PointerEvent(type, {
      bubbles: true, clientX: cx, clientY: cy, pointerId: 1, isPrimary: true, buttons: type === "pointerup" ? 0 : 1
    }));
    return [cx, cy];
  }

  // ---- 2.1 / 2.4: the cavity, its boundary and the ball of a point one drags ----------------
  function Cavity(root, opts) {
    opts = opts || {};
    var W = opts.width || 560, H = opts.height || 560;
    var f = frame(root, "Figures 2.1 and 2.4, live: drag pₙ₊₁", W, H,
                  "arrows move p (with Shift, ten times farther); Enter or Space shows the next of cavity, ball, both.");
    var self = this;
    this.svg = f.svg;
    this.sceneId = ++uid;  // its own triangulation in the library (DT.useScene)
    var gMesh = el("g", {}, f.svg), gWalk = el("g", {}, f.svg), gCav = el("g", {}, f.svg),
        gBall = el("g", {}, f.svg), gBnd = el("g", {}, f.svg), gPts = el("g", {}, f.svg), gP = el("g", {}, f.svg);
    var sizes = opts.sizes || [15, 100, 1000, 10000];
    var sel = labelled(f.controls, "points", "select", { "class": "dt-n" });
    sizes.forEach(function (n) { html("option", { value: n }, sel, "n = " + n); });
    var show = labelled(f.controls, "show", "select", { "class": "dt-show" });
    var modes = [["cavity", "cavity 𝒞 and its boundary ∂𝒞"], ["ball", "ball 𝓑 (the new triangles)"], ["both", "both"]];
    modes.forEach(function (m) { html("option", { value: m[0] }, show, m[1]); });
    show.value = "both";
    legend(f.legend, [
      { stroke: S.C_TRI, width: 1, text: "DTₙ, before pₙ₊₁ is inserted" },
      { fill: S.C_NEIGH, stroke: S.C_NEIGH_EDGE, text: "faces the walk to p visited" },
      { fill: S.C_CAVITY, stroke: S.C_TRI, text: "cavity 𝒞 (its inner edges thin)" },
      { stroke: S.C_CAVITY_EDGE, width: 3, text: "boundary ∂𝒞" },
      { stroke: S.C_BALL_EDGE, width: 2, text: "ball 𝓑 (in ball mode also filled)" },
      { dot: S.C_NEW, r: 5, text: "p, the point pₙ₊₁ (drag it, tap where it should go, or use the arrow keys)" }
    ]);
    this.report = null;
    this.setPoints = function (xy) {
      self.xy = xy;
      DT.useScene(self.sceneId);
      DT.sceneInit(xy, 0);
      var m = DT.sceneMesh();
      self.view = boxView(xy, W, H);
      clear(gMesh); clear(gPts);
      el("path", { d: triPath(self.view, m.coords, 0, m.count), fill: "none", stroke: S.C_TRI,
                   "stroke-width": xy.length > 2000 ? 0.4 : 1, "class": "mesh" }, gMesh);
      if (xy.length <= 2000) {
        for (var k = 0; k < xy.length; k += 2)
          el("circle", { cx: self.view.X(xy[k]), cy: self.view.Y(xy[k + 1]), r: 3, fill: S.C_POINT }, gPts);
      }
      self.meshTriangles = m.count;
      var b = self.view.box;
      self.moveTo(b[0] + 0.43 * (b[2] - b[0]), b[1] + 0.52 * (b[3] - b[1]));
    };
    // Places p at (x, y): the library walks to it and collects 𝒞, ∂𝒞 and 𝓑; the figure draws them
    // over the faces of the walk, and says in words what it drew.
    this.moveTo = function (x, y) {
      DT.useScene(self.sceneId);
      var r = DT.query(x, y), v = self.view, mode = show.value;
      clear(gWalk); clear(gCav); clear(gBall); clear(gBnd); clear(gP);
      polygons(gWalk, v, r.walkFaces, "walk", S.C_NEIGH, S.C_NEIGH_EDGE);
      // Inner edges of 𝒞 are drawn as the mesh's: only ∂𝒞 has the boundary's colour and width.
      if (mode !== "ball") polygons(gCav, v, r.cavityFaces, "cavity", S.C_CAVITY, S.C_TRI);
      if (mode !== "cavity")
        polygons(gBall, v, r.ballFaces, "ball", mode === "ball" ? S.C_BALL : "none", S.C_BALL_EDGE);
      r.boundaryEdges.forEach(function (e) {
        el("line", { "class": "boundary", x1: v.X(e[0]), y1: v.Y(e[1]), x2: v.X(e[2]), y2: v.Y(e[3]),
                     stroke: mode === "ball" ? S.C_BALL_EDGE : S.C_CAVITY_EDGE, "stroke-width": 3 }, gBnd);
      });
      el("circle", { cx: v.X(x), cy: v.Y(y), r: 6, fill: S.C_NEW, stroke: "white", "stroke-width": 1.5, "class": "p" }, gP);
      self.report = r;
      f.info.textContent = r.text;
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
    // Arrows: p moves by 1 % of the view (10 % with Shift), and stays inside it.
    keyboard(f.svg, function (dx, dy, big) {
      var b = self.view.box, k = big ? 0.1 : 0.01, p = self.report.p;
      self.moveTo(Math.min(b[2], Math.max(b[0], p[0] + dx * k * (b[2] - b[0]))),
                  Math.min(b[3], Math.max(b[1], p[1] + dy * k * (b[3] - b[1]))));
    }, function () {
      var i = modes.map(function (m) { return m[0]; }).indexOf(show.value);
      self.setShow(modes[(i + 1) % modes.length][0]);
    });
    this.setSize = function (n) { sel.value = n; self.setPoints(randomPoints(n, 2024)); };
    sel.addEventListener("change", function () { self.setSize(+sel.value); });
    show.addEventListener("change", function () { if (self.report) self.moveTo(self.report.p[0], self.report.p[1]); });
    this.setShow = function (m) { show.value = m; self.moveTo(self.report.p[0], self.report.p[1]); };
    this.pointer = function (type, x, y) { return pointerAt(self, type, x, y); };
    this.counts = function () {
      return { cavity: f.svg.querySelectorAll(".cavity").length, ball: f.svg.querySelectorAll(".ball").length,
               boundary: f.svg.querySelectorAll(".boundary").length, walk: f.svg.querySelectorAll(".walk").length };
    };
    this.info = f.info;
    this.setSize(sizes[0]);
  }

  // ---- 2.5: Bowyer-Watson step by step, from the super-triangles, with the walk ------------
  function BowyerWatson(root, opts) {
    opts = opts || {};
    var W = opts.width || 560, H = opts.height || 560;
    var f = frame(root, "Figure 2.5, live: Bowyer-Watson one insertion at a time", W, H,
                  "Enter or Space inserts the next point.");
    var self = this;
    this.svg = f.svg;
    this.sceneId = ++uid;  // its own triangulation in the library (DT.useScene)
    // The faces of the walk and of the cavity (before the insertion) under the new mesh.
    var gWalk = el("g", {}, f.svg), gCav = el("g", {}, f.svg), gMesh = el("g", {}, f.svg),
        gPts = el("g", {}, f.svg), gMark = el("g", {}, f.svg);
    var btn = html("button", { "class": "dt-step", type: "button" }, f.controls, "insert the next point");
    var reset = html("button", { "class": "dt-reset", type: "button" }, f.controls, "start again");
    var which = labelled(f.controls, "points", "select", { "class": "dt-which" });
    html("option", { value: "fig25" }, which, "the 9 points of Figure 2.5");
    html("option", { value: "random" }, which, "20 random points");
    legend(f.legend, [
      { stroke: S.C_TRI, width: 1, text: "DT_k, with the super-triangles" },
      { fill: S.C_NEIGH, stroke: S.C_NEIGH_EDGE, text: "faces the walk to the new point visited" },
      { fill: S.C_CAVITY, stroke: S.C_CAVITY_EDGE, text: "its cavity 𝒞 (before the insertion)" },
      { dot: "white", stroke: S.C_POINT, r: 3, text: "a point still to insert" },
      { dot: S.C_POINT, r: 3, text: "an inserted point" },
      { dot: S.C_NEW, r: 5, text: "the point just inserted" }
    ]);
    this.nSearchTotal = 0;
    this.steps = 0;
    function drawMesh() {
      var m = DT.sceneMesh();
      clear(gMesh);
      el("path", { d: triPath(self.view, m.coords, 0, m.count), fill: "none", stroke: S.C_TRI,
                   "stroke-width": 1, "class": "mesh" }, gMesh);
      self.meshTriangles = m.count;
      return m;
    }
    // Starts from xy (Figure 2.5's points in their order and super-square when not given, as
    // the static figure; "random": 20 points in super-triangles 10 times their box).
    this.start = function (xy) {
      var fig25 = which.value === "fig25";
      DT.useScene(self.sceneId);
      self.xy = xy || (fig25 ? new Float64Array(DT_FIGURES.fig25.xy) : randomPoints(opts.n || 20, 7));
      DT.sceneInit(self.xy, 1, fig25 ? DT_FIGURES.fig25.factor : 10);
      f.info.textContent = DT.text();
      self.nSearchTotal = 0;
      self.steps = 0;
      self.left = self.xy.length / 2;
      // A small super-square is drawn whole; one 10 times the box of the points only in part.
      self.view = fig25 ? boxView(DT.sceneMesh().coords, W, H) : new View(-0.6, -0.6, 1.6, 1.6, W, H);
      clear(gWalk); clear(gCav); clear(gPts); clear(gMark);
      drawMesh();
      // The points still to insert, hollow as in the static Figure 2.5; each is filled when
      // inserted.
      for (var k = 0; k < self.xy.length; k += 2)
        el("circle", { cx: self.view.X(self.xy[k]), cy: self.view.Y(self.xy[k + 1]), r: 3,
                       fill: "white", stroke: S.C_POINT, "stroke-width": 1, "class": "pending" }, gPts);
    };
    // Inserts the next point: draws the faces its walk visited and its cavity, then the new mesh.
    this.step = function () {
      if (self.left === 0) return null;
      DT.useScene(self.sceneId);
      var r = DT.step(), v = self.view;
      clear(gWalk); clear(gCav);
      polygons(gWalk, v, r.walkFaces, "walk", S.C_NEIGH, S.C_NEIGH_EDGE);
      polygons(gCav, v, r.cavityFaces, "cavity", S.C_CAVITY, S.C_CAVITY_EDGE);
      drawMesh();
      el("circle", { cx: v.X(r.p[0]), cy: v.Y(r.p[1]), r: 3, fill: S.C_POINT }, gPts);
      clear(gMark);
      el("circle", { cx: v.X(r.p[0]), cy: v.Y(r.p[1]), r: 6, fill: S.C_NEW }, gMark);
      self.nSearchTotal += r.nSearch;
      self.steps++;
      self.left = r.left;
      self.report = r;
      f.info.textContent = r.text;
      return r;
    };
    btn.addEventListener("click", function () { self.step(); });
    reset.addEventListener("click", function () { self.start(); });
    which.addEventListener("change", function () { self.start(); });
    keyboard(f.svg, null, function () { self.step(); });
    this.counts = function () {
      return { walk: f.svg.querySelectorAll(".walk").length, cavity: f.svg.querySelectorAll(".cavity").length };
    };
    this.click = function () { btn.dispatchEvent(new MouseEvent("click", { bubbles: true })); };
    this.setPoints = function (m) { which.value = m; self.start(); };
    this.info = f.info;
    this.start();
  }

  // ---- 2.7 / 2.8: the predicate maps, naive against exact, with zoom --------------------------
  // The colour of a cell's pixel: signs get a second cue beside colour (negative cells are
  // hatched with white diagonals, zero cells dotted, positive ones plain), so the map reads
  // without telling red from green.
  function signPixel(sign, px, py) {
    if (sign < 0 && (px + py) % 4 === 0) return "#ffffff";
    if (sign === 0 && px % 2 === 0 && py % 2 === 0) return "#000000";
    return sign < 0 ? S.C_MINUS : sign > 0 ? S.C_PLUS : S.C_ZERO;
  }
  function rgb(c) {
    var m = /^#(..)(..)(..)$/.exec(c);
    return [parseInt(m[1], 16), parseInt(m[2], 16), parseInt(m[3], 16)];
  }
  // A swatch canvas painted pixel by pixel with colour(px, py) (the legend of the maps).
  function swatch(colour) {
    var c = html("canvas", { width: 20, height: 12, "class": "dt-swatch", "aria-hidden": "true" });
    var ctx = c.getContext("2d"), img = ctx.createImageData(20, 12);
    for (var y = 0; y < 12; y++)
      for (var x = 0; x < 20; x++) {
        var k = 4 * (y * 20 + x), q = rgb(colour(x, y));
        img.data[k] = q[0]; img.data[k + 1] = q[1]; img.data[k + 2] = q[2]; img.data[k + 3] = 255;
      }
    ctx.putImageData(img, 0, 0);
    return c;
  }
  function PredicateMap(root, opts) {
    opts = opts || {};
    var N = opts.n || 256, PX = opts.pixel || 2, R = DT.record;
    var f = frame(root, "Figures 2.7 and 2.8, live: orient2d near a degenerate line", N * PX, N * PX,
                  "arrows move the cursor one cell (with Shift, 16 cells); + and - zoom about the cursor; " +
                  "Enter or Space shows the next map (naive, exact, stage, wrong cells).");
    var self = this;
    this.svg = f.svg;
    f.svg.style.display = "none";
    f.svg.removeAttribute("tabindex");
    var canvas = html("canvas", { width: N * PX, height: N * PX, "class": "dt-map", tabindex: 0, role: "application",
                                  "aria-label": "Figures 2.7 and 2.8, live: the predicate map",
                                  "aria-describedby": f.id + "-keys " + f.id + "-info " + f.id + "-cell" });
    root.insertBefore(canvas, f.controls);
    var cellLine = html("div", { "class": "dt-live-info", id: f.id + "-cell", "aria-live": "polite" }, root);
    var what = labelled(f.controls, "show", "select", { "class": "dt-what" });
    var modes = [["naive", "naive double sign"], ["exact", "exact sign (the kernel's)"],
                 ["stage", "stage that decided it"], ["diff", "where naive is wrong"]];
    modes.forEach(function (o) { html("option", { value: o[0] }, what, o[1]); });
    var kind = labelled(f.controls, "predicate", "select", { "class": "dt-kind" });
    R.mapKinds.forEach(function (name, k) { html("option", { value: String(k) }, kind, name); });
    var zin = html("button", { "class": "dt-zin", type: "button" }, f.controls, "zoom in");
    var zout = html("button", { "class": "dt-zout", type: "button" }, f.controls, "zoom out");
    // Figure 2.7's configuration: b(12,12), c(24,24), a(1/2 + i eps, 1/2 + j eps), eps = 2^-53;
    // for incircle, a(1/2,-47/2), b(49/2,-47/2), c(49/2,1/2) and d moving (robustness.h).
    var EPS = Math.pow(2, -53);
    this.step = EPS;
    this.zoomLevel = 0;
    this.x0 = 0.5;
    this.y0 = 0.5;
    this.cursor = [0, 0];
    function points(k) {
      return k === 2 ? [[0.5, -23.5], [24.5, -23.5], [24.5, 0.5]] : [[12, 12], [24, 24], [0, 0]];
    }
    // One unit in the last place of the largest coordinate the view shows: cells narrower
    // than that would round to the same point and repeat.
    function ulpOfView() {
      var m = Math.max(Math.abs(self.x0), Math.abs(self.y0), Math.abs(self.x0 + N * self.step),
                       Math.abs(self.y0 + N * self.step));
      return m === 0 ? Number.MIN_VALUE : Math.pow(2, Math.floor(Math.log2(m)) - 52);
    }
    // The legend of the mode shown: sign colours with their second cue, stage colours with the
    // C++'s names and counts, or the wrong cells.
    function drawLegend(mode) {
      clear(f.legend);
      if (mode === "naive" || mode === "exact")
        legend(f.legend, [-1, 0, 1].map(function (s) {
          return { canvas: swatch(function (x, y) { return signPixel(s, x, y); }),
                   text: R.signs[s + 1] + (s < 0 ? " (hatched)" : s === 0 ? " (dotted)" : " (plain)") };
        }));
      else if (mode === "stage")
        legend(f.legend, R.stages.map(function (name, s) {
          return { fill: SERIES[s % SERIES.length], text: name + ": " + self.stages[s] + (self.stages[s] === 1 ? " cell" : " cells"), key: "stage-" + s };
        }));
      else
        legend(f.legend, [{ fill: S.C_CONFLICT, text: "the naive sign is wrong" },
                          { fill: "#ffffff", stroke: "#767676", text: "the naive sign is right" }]);
    }
    function paint() {
      var ctx = canvas.getContext("2d"), mode = what.value, cells = self.cells;
      var img = ctx.createImageData(N * PX, N * PX), d = img.data, cache = {};
      for (var py = 0; py < N * PX; py++)
        for (var px = 0; px < N * PX; px++) {
          var i = Math.floor(px / PX), j = N - 1 - Math.floor(py / PX), o = 3 * (j * N + i), c;
          if (mode === "naive") c = signPixel(cells[o], px, py);
          else if (mode === "exact") c = signPixel(cells[o + 1], px, py);
          else if (mode === "stage") c = SERIES[cells[o + 2] % SERIES.length];
          else c = cells[o] !== cells[o + 1] ? S.C_CONFLICT : "#ffffff";
          var q = cache[c] || (cache[c] = rgb(c)), k = 4 * (py * N * PX + px);
          d[k] = q[0]; d[k + 1] = q[1]; d[k + 2] = q[2]; d[k + 3] = 255;
        }
      ctx.putImageData(img, 0, 0);
      // The cursor: a black and a white square around its cell, seen on every colour.
      var cx = self.cursor[0] * PX, cy = (N - 1 - self.cursor[1]) * PX;
      ctx.lineWidth = 1;
      ctx.strokeStyle = "#000000";
      ctx.strokeRect(cx - 2.5, cy - 2.5, PX + 5, PX + 5);
      ctx.strokeStyle = "#ffffff";
      ctx.strokeRect(cx - 3.5, cy - 3.5, PX + 7, PX + 7);
    }
    // The cursor's cell in words (the C++ evaluates it again and names its signs and stage).
    function describeCursor() {
      var k = +kind.value, p = points(k);
      self.cursorCell = DT.mapCell(k, self.cursor[0], self.cursor[1], self.x0, self.y0, self.step, p[0], p[1], p[2]);
      cellLine.textContent = DT.text();
    }
    this.draw = function () {
      var k = +kind.value, p = points(k);
      var m = DT.predicateMap(k, self.x0, self.y0, self.step, N, p[0], p[1], p[2]);
      self.cells = m.cells;
      self.stages = m.stages;
      self.wrongCells = m.wrong;
      f.info.textContent = DT.text();
      zin.disabled = self.step / 2 < ulpOfView();
      paint();
      drawLegend(what.value);
      describeCursor();
      return self;
    };
    // Zooms by 2^d about the cursor: its cell keeps its point, the others close in or spread out.
    // Past one unit in the last place per cell it refuses (cells would repeat).
    this.zoom = function (d) {
      var st = self.step * Math.pow(2, -d);
      if (d > 0 && st < ulpOfView()) return self;
      var mx = self.x0 + self.cursor[0] * self.step, my = self.y0 + self.cursor[1] * self.step;
      self.x0 = mx - self.cursor[0] * st;
      self.y0 = my - self.cursor[1] * st;
      self.zoomLevel += d;
      self.step = st;
      return self.draw();
    };
    this.moveCursor = function (i, j) {
      self.cursor = [Math.max(0, Math.min(N - 1, i)), Math.max(0, Math.min(N - 1, j))];
      paint();
      describeCursor();
      return self;
    };
    // The cell under a pointer event: the canvas's box on screen scaled to its N x N cells.
    function eventCell(ev) {
      var r = canvas.getBoundingClientRect();
      return [Math.floor((ev.clientX - r.left) / r.width * N), N - 1 - Math.floor((ev.clientY - r.top) / r.height * N)];
    }
    canvas.addEventListener("pointerdown", function (ev) { var c = eventCell(ev); self.moveCursor(c[0], c[1]); });
    canvas.addEventListener("pointermove", function (ev) {
      if (ev.buttons) { var c = eventCell(ev); self.moveCursor(c[0], c[1]); }
    });
    // The wheel zooms about the cell under the pointer.
    canvas.addEventListener("wheel", function (ev) {
      var c = eventCell(ev);
      self.cursor = [Math.max(0, Math.min(N - 1, c[0])), Math.max(0, Math.min(N - 1, c[1]))];
      self.zoom(ev.deltaY < 0 ? 1 : -1);
      ev.preventDefault();
    });
    keyboard(canvas, function (dx, dy, big) {
      self.moveCursor(self.cursor[0] + dx * (big ? 16 : 1), self.cursor[1] + dy * (big ? 16 : 1));
    }, function () {
      var i = modes.map(function (m) { return m[0]; }).indexOf(what.value);
      self.set(modes[(i + 1) % modes.length][0]);
    }, function (key) {
      if (key === "+" || key === "=") self.zoom(1);
      else if (key === "-") self.zoom(-1);
      else return false;
      return true;
    });
    // Back to Figure 2.7's view: the corner (1/2, 1/2) at cell (0, 0), one ulp per cell.
    this.home = function () { self.step = EPS; self.zoomLevel = 0; self.x0 = 0.5; self.y0 = 0.5; return self.draw(); };
    this.set = function (m, k) { what.value = m; if (k !== undefined) kind.value = String(k); return self.draw(); };
    what.addEventListener("change", function () { self.draw(); });
    kind.addEventListener("change", function () { self.draw(); });
    zin.addEventListener("click", function () { self.zoom(1); });
    zout.addEventListener("click", function () { self.zoom(-1); });
    this.canvas = canvas;
    this.legend = f.legend;
    this.info = f.info;
    this.cellLine = cellLine;
    this.draw();
  }

  // ---- 2.11 / 2.12: the Hilbert order with its depth, and BRIO rounds ----------------------
  function Hilbert(root, opts) {
    opts = opts || {};
    var W = opts.width || 560, H = opts.height || 560;
    var f = frame(root, "Figures 2.11 and 2.12, live: Hilbert depth and BRIO rounds", W, H,
                  "Left and Right change the depth, Up and Down the last BRIO round drawn; Enter or Space " +
                  "switches between the Hilbert order and the BRIO rounds.");
    var self = this;
    this.svg = f.svg;
    var g = el("g", {}, f.svg);
    var depth = labelled(f.controls, "depth", "input", { type: "range", min: 1, max: 10, value: 3, "class": "dt-depth" });
    var mode = labelled(f.controls, "order", "select", { "class": "dt-mode" });
    html("option", { value: "hilbert" }, mode, "Hilbert order");
    html("option", { value: "brio" }, mode, "BRIO rounds");
    var round = labelled(f.controls, "rounds drawn", "input", { type: "range", min: 1, max: 1, value: 1, "class": "dt-round" });
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
      var text = DT.text();
      self.order = order;
      self.roundStarts = starts;
      var items = [];
      for (var r = 0; r < starts.length; r++) {
        var from = starts[r], to = Math.min(r + 1 < starts.length ? starts[r + 1] : n, last);
        if (from >= to) break;
        var pts = [], c = SERIES[r % SERIES.length];
        for (var k = from; k < to; k++) pts.push(v.X(xy[2 * order[k]]) + "," + v.Y(xy[2 * order[k] + 1]));
        el("polyline", { points: pts.join(" "), fill: "none", stroke: c, "stroke-width": 1.5, "class": "curve" }, g);
        for (k = from; k < to; k++)
          el("circle", { cx: v.X(xy[2 * order[k]]), cy: v.Y(xy[2 * order[k] + 1]), r: 2.5, fill: c, "class": "pt" }, g);
        items.push({ stroke: c, text: mode.value === "hilbert" ? "the order, point to point" : "round " + (r + 1) });
      }
      clear(f.legend);
      legend(f.legend, items);
      self.drawn = last;
      f.info.textContent = text + (mode.value === "brio" ? " Rounds 1 to " + round.value + " drawn." : "");
      return self;
    };
    this.set = function (m, d, r) {
      mode.value = m; depth.value = d; if (r !== undefined) round.value = r; return self.draw();
    };
    keyboard(f.svg, function (dx, dy) {
      if (dx) depth.value = +depth.value + dx;
      if (dy && mode.value === "brio") round.value = +round.value + dy;
      self.draw();
    }, function () { self.set(mode.value === "hilbert" ? "brio" : "hilbert", depth.value); });
    [depth, mode, round].forEach(function (c) { c.addEventListener("input", self.draw); c.addEventListener("change", self.draw); });
    this.info = f.info;
    this.draw();
  }

  // ---- 2.3.6: recovering DT(S) from DT(S0 ∪ S), one flip at a time --------------------------
  function Flips(root, opts) {
    opts = opts || {};
    var W = opts.width || 560, H = opts.height || 560;
    var f = frame(root, "Section 2.3.6, live: the recovery flips, one at a time", W, H,
                  "Enter or Space does the next flip.");
    var self = this;
    this.svg = f.svg;
    this.sceneId = ++uid;  // its own triangulation in the library (DT.useScene)
    var gMesh = el("g", {}, f.svg), gFlip = el("g", {}, f.svg), gPts = el("g", {}, f.svg);
    var btn = html("button", { "class": "dt-flip", type: "button" }, f.controls, "next flip");
    var reset = html("button", { "class": "dt-reset", type: "button" }, f.controls, "start again");
    legend(f.legend, [
      { stroke: S.C_TRI, width: 1, text: "triangles of S" },
      { stroke: S.C_SUPER, width: 1, dash: "4 3", text: "triangles touching a super vertex (dashed)" },
      { stroke: S.C_CONFLICT, width: 3, dash: "6 4", text: "the edge just flipped away (dashed)" },
      { stroke: S.C_BALL_EDGE, width: 3, text: "the edge it became" },
      { dot: S.C_POINT, r: 3, text: "a vertex, labelled p and its number" }
    ]);
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
      return m;
    }
    this.start = function (xy) {
      self.xy = xy || randomPoints(opts.n || 25, 5);
      DT.useScene(self.sceneId);
      // Super-triangles 1.25 times the box, as the static frames: small enough to need flips.
      DT.sceneInit(self.xy, 1, 1.25);
      for (var left = self.xy.length / 2; left > 0;) left = DT.step().left;
      self.total = DT.flipPrepare();
      f.info.textContent = DT.text();
      self.done = 0;
      self.finished = false;
      // The whole of DT(S0 ∪ S), super vertices included, fills the drawing.
      self.view = boxView(DT.sceneMesh().coords, W, H);
      clear(gFlip); clear(gPts);
      var m = drawMesh(), seen = {};
      // Every vertex, super vertices too, with the number the text names it by.
      for (var t = 0; t < 3 * m.count; t++) {
        var id = m.ids[t], x = m.coords[2 * t], y = m.coords[2 * t + 1];
        if (seen[id]) continue;
        seen[id] = true;
        el("circle", { cx: self.view.X(x), cy: self.view.Y(y), r: 3, fill: S.C_POINT }, gPts);
        el("text", { x: self.view.X(x) + 4, y: self.view.Y(y) - 4, "font-size": 11, fill: "#000000",
                     "class": "label" }, gPts).textContent = "p" + id;
      }
    };
    this.step = function () {
      if (self.finished) return null;
      DT.useScene(self.sceneId);
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
      }
      f.info.textContent = r.text;
      return r;
    };
    btn.addEventListener("click", function () { self.step(); });
    reset.addEventListener("click", function () { self.start(self.xy); });
    keyboard(f.svg, null, function () { self.step(); });
    this.click = function () { btn.dispatchEvent(new MouseEvent("click", { bubbles: true })); };
    this.info = f.info;
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
