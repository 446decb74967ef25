// The browser test of the live figures (ctest web_browser, web/run_browser_test.sh): drives
// every figure through its API and through synthetic pointer events, and checks
//  - the WebAssembly triangulation equals the native one (DT_CASES, written by
//    web_native_cases) on hard inputs, triangle for triangle;
//  - the drawn SVG has as many cavity, ball, boundary and walk elements as the C++ reports;
//  - the C++ reports agree with independent checks (brute-force conflict count with the exact
//    incircle, N_search = faces traced, |B| = |C| + 2, closed-form signs of the maps);
//  - the names a figure shows are the C++'s (Figure 2.7's largest stage is labelled GMP);
//  - a tap lands p under the finger at this window's width (run at 390 and 1280 px);
//  - keys alone move p and step every figure, and say what changed in the aria-live line;
//  - axe-core finds no WCAG 2.1 A/AA violation on the page after every figure was driven;
//  - nothing was written to the console as an error.
// The verdict goes into <pre id="verdict">, which headless Chromium dumps.
"use strict";
(function () {
  var results = [];
  function ok(name, cond, detail) {
    results.push((cond ? "PASS " : "FAIL ") + name + (cond || !detail ? "" : ": " + detail));
    return cond;
  }
  function equalArrays(a, b) {
    if (a.length !== b.length) return "lengths " + a.length + " and " + b.length;
    for (var i = 0; i < a.length; i++)
      if (a[i] !== b[i]) return "first difference at " + i + ": " + a[i] + " vs " + b[i];
    return "";
  }
  function attempt(name, f) {
    try { f(); } catch (e) { ok(name, false, "exception " + (e && e.stack ? e.stack : e)); }
  }
  function finish() {
    if (DT_ERRORS.length) ok("console shows no errors", false, DT_ERRORS.join(" | "));
    else ok("console shows no errors", true);
    var failed = results.filter(function (r) { return r.indexOf("FAIL") === 0; }).length;
    var verdict = results.join("\n") + "\n" + "RESULT: " + (failed ? "FAIL" : "PASS") + "\n" +
      (results.length - failed) + " passed, " + failed + " failed\n";
    document.getElementById("verdict").textContent = verdict;
    // In the frame of test_390.html: the verdict goes to the page the runner reads.
    if (window.parent !== window) window.parent.postMessage({ verdict: verdict }, "*");
  }

  // Brute force: the finite mesh triangles whose circumcircle strictly contains p (exact
  // incircle of the library, each triangle tested; the figure's count comes from a walk and a
  // depth-first search instead).
  function bruteCavity(fig, p) {
    DT.useScene(fig.sceneId);
    var m = DT.sceneMesh(), c = m.coords, k = 0;
    for (var t = 0; t < m.count; t++) {
      var o = 6 * t;
      if (DT.incircle(c[o], c[o + 1], c[o + 2], c[o + 3], c[o + 4], c[o + 5], p[0], p[1]).exact > 0) k++;
    }
    return k;
  }

  function testCases() {
    DT_CASES.forEach(function (c) {
      attempt("wasm = native fast kernel: " + c.name, function () {
        // Unchecked here, so that a difference is found by the comparison itself; the exact
        // check of the WebAssembly result is the next test.
        var tri = DT.triangulate(new Float64Array(c.xy), false);
        var d = equalArrays(tri, c.fast);
        ok("wasm = native fast kernel: " + c.name + " (" + c.fast.length / 3 + " triangles)", d === "", d);
      });
      attempt("wasm result passes checkDelaunay: " + c.name, function () {
        ok("wasm result passes checkDelaunay: " + c.name, DT.triangulate(new Float64Array(c.xy), true).length === c.fast.length);
      });
      attempt("wasm = native listings: " + c.name, function () {
        var tri = DT.triangulateListings(new Float64Array(c.xy));
        var d = equalArrays(tri, c.listings);
        ok("wasm = native listings: " + c.name, d === "", d);
      });
    });
  }

  function figure(id) { return document.getElementById(id).dtFigure; }

  function testCavity() {
    var fig = figure("cavity");
    [15, 1000].forEach(function (n) {
      fig.setSize(n);
      var path = [[0.3, 0.3], [0.5, 0.52], [0.51, 0.53], [0.7, 0.4], [0.2, 0.8], [0.98, 0.5], [0.02, 0.02]];
      fig.pointer("pointerdown", path[0][0], path[0][1]);
      path.forEach(function (q) {
        fig.pointer("pointermove", q[0], q[1]);
        var r = fig.report, cnt = fig.counts(), tag = "2.1/2.4 n=" + n + " p=(" + q + ")";
        ok(tag + " p follows the pointer", Math.abs(r.p[0] - q[0]) < 0.01 && Math.abs(r.p[1] - q[1]) < 0.01,
           "p at " + r.p);
        ok(tag + " drawn cavity = C++ |C|", cnt.cavity === r.cavityFinite, cnt.cavity + " vs " + r.cavityFinite);
        ok(tag + " drawn ball = C++ |B|", cnt.ball === r.ballFinite, cnt.ball + " vs " + r.ballFinite);
        ok(tag + " drawn boundary = C++ boundary", cnt.boundary === r.boundaryFinite,
           cnt.boundary + " vs " + r.boundaryFinite);
        ok(tag + " drawn walk = C++ walk", cnt.walk === r.walkFinite && r.walk > 0, cnt.walk + " vs " + r.walkFinite);
        ok(tag + " |C| = brute-force conflicts", r.cavityFinite === bruteCavity(fig, r.p),
           r.cavityFinite + " vs " + bruteCavity(fig, r.p));
        if (!r.outside && !r.duplicate)
          ok(tag + " |B| = |C| + 2 inside the hull", r.ball === r.cavity + 2, r.ball + " vs " + r.cavity);
      });
      fig.pointer("pointerup", 0.02, 0.02);
      var before = fig.report;
      fig.pointer("pointermove", 0.6, 0.6);  // not dragging any more: p stays
      ok("2.1/2.4 n=" + n + " p stays after pointerup", fig.report === before, "moved");
    });
    ["cavity", "ball"].forEach(function (m) {
      fig.setShow(m);
      var cnt = fig.counts(), r = fig.report;
      ok("2.1/2.4 show " + m + " draws only it", m === "cavity" ? cnt.ball === 0 && cnt.cavity === r.cavityFinite
                                                              : cnt.cavity === 0 && cnt.ball === r.ballFinite,
         JSON.stringify(cnt));
    });
    // A point on a vertex: no cavity, said so.
    fig.setSize(15);
    var r = fig.moveTo(fig.xy[0], fig.xy[1]);
    ok("2.1/2.4 a point on a vertex has no cavity", r.duplicate && r.cavity === 0 && fig.counts().cavity === 0,
       JSON.stringify(r));
    // Outside the hull (a corner of the view, beyond the points' box) and inside it: said so,
    // and checked against the points' hull by orientation (the hull of the drawn mesh edges).
    var b = fig.view.box;
    [[b[0], b[1], true], [b[2], b[3], true], [0.5 * (b[0] + b[2]), 0.5 * (b[1] + b[3]), false]].forEach(function (q) {
      var r = fig.moveTo(q[0], q[1]);
      ok("2.1/2.4 p at (" + q[0].toFixed(3) + ", " + q[1].toFixed(3) + ") is " + (q[2] ? "outside" : "inside") + " the hull",
         r.outside === q[2] && (fig.info.textContent.indexOf("outside the convex hull") >= 0) === q[2],
         "outside " + r.outside + ": " + fig.info.textContent);
    });
    // The aria-live line is the C++'s sentence, with the drawn counts.
    r = fig.moveTo(0.5, 0.5);
    var t = fig.info.textContent;
    ok("2.1/2.4 the live line states |C|, |dC|, |B| and the walk",
       t.indexOf("|𝒞| = " + r.cavityFinite) >= 0 && t.indexOf("|∂𝒞| = " + r.boundaryFinite) >= 0 &&
       t.indexOf("|𝓑| = " + r.ballFinite) >= 0 && t.indexOf("visits " + r.walk + " face") >= 0 &&
       fig.info.getAttribute("aria-live") === "polite", t);
  }

  function testBowyer() {
    var fig = figure("bowyer");
    ok("2.5 starts from Figure 2.5's nine points", fig.xy.length === 18 &&
       equalArrays(Array.prototype.slice.call(fig.xy), DT_FIGURES.fig25.xy) === "", String(fig.xy));
    [["random", 20], ["fig25", 9]].forEach(function (w) {
      fig.setPoints(w[0]);
      ok("2.5 " + w[0] + " points: " + w[1], fig.xy.length === 2 * w[1], fig.xy.length / 2);
    });
    var n = fig.xy.length / 2, allOk = true, sum = 0;
    for (var i = 0; i < n; i++) {
      fig.click();
      var r = fig.report, cnt = fig.counts();
      sum += r.nSearch;
      allOk = ok("2.5 step " + (i + 1) + " N_search = faces traced", r.nSearch === r.walk, r.nSearch + " vs " + r.walk) && allOk;
      ok("2.5 step " + (i + 1) + " drawn walk = C++ walk", cnt.walk === r.walkFinite, cnt.walk + " vs " + r.walkFinite);
      ok("2.5 step " + (i + 1) + " drawn cavity = C++ |C|", cnt.cavity === r.cavityFinite, cnt.cavity + " vs " + r.cavityFinite);
      ok("2.5 step " + (i + 1) + " |B| = |C| + 2", r.ball === r.cavity + 2, r.ball + " vs " + r.cavity);
    }
    ok("2.5 N_search summed", fig.nSearchTotal === sum && sum >= n, fig.nSearchTotal + " vs " + sum);
    ok("2.5 DT(S0 u S) has 2n + 2 triangles", fig.meshTriangles === 2 * n + 2, fig.meshTriangles + " for n=" + n);
    ok("2.5 no point left", fig.left === 0 && fig.step() === null, "left " + fig.left);
    ok("2.5 the live line states N_search summed", fig.info.textContent.indexOf(sum + " summed") >= 0, fig.info.textContent);
  }

  // The exact orientation map of Figure 2.7 against its closed form: b, c on y = x, so
  // O(a, b, c) = sign(ay - ax) for the rounded coordinates of a.
  function checkExactMap(fig, tag) {
    var N = 256, c = fig.cells, bad = 0;
    for (var j = 0; j < N; j++)
      for (var i = 0; i < N; i++) {
        var ax = fig.x0 + i * fig.step, ay = fig.y0 + j * fig.step;
        if (c[3 * (j * N + i) + 1] !== Math.sign(ay - ax)) bad++;
      }
    ok("2.7 exact map = sign(ay - ax) " + tag, bad === 0, bad + " cells differ");
  }

  function testPredicates() {
    var fig = figure("predicates");
    var N = 256, EPS = Math.pow(2, -53);
    fig.set("exact", 0);
    fig.home();
    checkExactMap(fig, "at Figure 2.7's view");
    // Finer than one ulp per cell the cells would repeat: the zoom refuses.
    fig.zoom(1);
    ok("2.7 no zoom below one ulp per cell", fig.step === EPS && fig.canvas.parentNode.querySelector(".dt-zin").disabled,
       fig.step / EPS);
    // The zoom follows the cursor: its cell keeps its point.
    fig.moveCursor(100, 40);
    var mx = fig.x0 + 100 * fig.step, my = fig.y0 + 40 * fig.step;
    fig.zoom(-3);
    ok("2.7 zooming out keeps the cursor's point", fig.x0 + 100 * fig.step === mx && fig.y0 + 40 * fig.step === my &&
       fig.step === 8 * EPS, [fig.x0 + 100 * fig.step - mx, fig.step / EPS]);
    checkExactMap(fig, "zoomed out 8 times about cell (100, 40)");
    fig.zoom(2);
    checkExactMap(fig, "zoomed back in 4 times");
    fig.home();
    var stages = fig.stages.reduce(function (a, b) { return a + b; }, 0);
    ok("2.7 every cell has a stage", stages === N * N, stages);
    ok("2.7 naive map is wrong somewhere", fig.wrongCells > 0, fig.wrongCells);
    ["naive", "exact", "stage", "diff"].forEach(function (m) {
      fig.set(m, 0);
      var px = fig.canvas.getContext("2d").getImageData(0, 0, 1, 1).data;
      ok("2.7 mode " + m + " draws", px[3] === 255, "alpha " + px[3]);
    });
    // The legend of the stages: names from the C++ record, counts from the C++ map. In
    // Figure 2.7 the exact GMP stage decides most cells (the points are on a line).
    fig.set("stage", 0);
    var best = null, items = fig.legend.querySelectorAll("li");
    items.forEach(function (li) {
      var m = /^(.*): (\d+) cells?$/.exec(li.textContent.trim());
      if (m && (!best || +m[2] > best.count)) best = { name: m[1], count: +m[2] };
    });
    var gmp = 0;
    for (var t = 2; t < fig.cells.length; t += 3) {
      if (DT.record.stages[fig.cells[t]] === "GMP") gmp++;
    }
    ok("2.7 largest stage in the legend is GMP with its count", best && best.name === "GMP" && best.count === gmp &&
       items.length === DT.record.stages.length, JSON.stringify(best) + " vs GMP " + gmp);
    // The cursor's sentence names the stage of its cell, as the C++ evaluates it again.
    fig.moveCursor(3, 5);
    var cell = fig.cells.subarray(3 * (5 * N + 3), 3 * (5 * N + 3) + 3);
    ok("2.7 the cursor's line names its cell's stage", fig.cellLine.textContent.indexOf("decided by the stage " +
       DT.record.stages[cell[2]]) >= 0 && fig.cursorCell.stage === cell[2], fig.cellLine.textContent);
    fig.set("exact", 2);
    var c = fig.cells, bad = 0;
    for (var j = 0; j < N; j++)
      for (var i = 0; i < N; i++) {
        var want = j < i ? 1 : (i === 0 && j === 0 ? 0 : -1);
        if (c[3 * (j * N + i) + 1] !== want) bad++;
      }
    ok("2.8 exact incircle map = closed form", bad === 0, bad + " cells differ");
    // The zoom buttons, through click events.
    fig.set("exact", 0);
    fig.home();
    fig.canvas.parentNode.querySelector(".dt-zout").dispatchEvent(new MouseEvent("click", { bubbles: true }));
    ok("2.7 zoom-out button doubles the cell size", fig.step === 2 * EPS, fig.step / EPS);
    fig.home();
  }

  function testHilbert() {
    var fig = figure("hilbert");
    var n = fig.xy.length / 2;
    [1, 4, 10].forEach(function (d) {
      fig.set("hilbert", d);
      var seen = new Uint8Array(n), perm = true;
      for (var k = 0; k < n; k++) { if (seen[fig.order[k]]) perm = false; seen[fig.order[k]] = 1; }
      ok("2.11 depth " + d + " order is a permutation", perm && fig.order.length === n, "");
      ok("2.11 depth " + d + " draws every point", fig.svg.querySelectorAll(".pt").length === n,
         fig.svg.querySelectorAll(".pt").length);
    });
    var slider = fig.svg.parentNode.querySelector(".dt-depth");
    slider.value = 6;
    slider.dispatchEvent(new Event("input", { bubbles: true }));
    ok("2.11 the depth slider redraws", fig.svg.parentNode.querySelector(".dt-live-info").textContent.indexOf("depth 6") >= 0,
       fig.svg.parentNode.querySelector(".dt-live-info").textContent);
    fig.set("brio", 8, 99);
    var s = fig.roundStarts, R = s.length;
    ok("2.12 BRIO rounds start at 0 and increase", s[0] === 0 && s.every(function (v, i) { return !i || v > s[i - 1]; }),
       JSON.stringify(s));
    ok("2.12 the last BRIO round holds the larger half", n - s[R - 1] === Math.ceil(n / 2), n - s[R - 1]);
    for (var r = 1; r <= R; r++) {
      fig.set("brio", 8, r);
      var want = r < R ? s[r] : n;
      ok("2.12 rounds 1.." + r + " draw " + want + " points", fig.svg.querySelectorAll(".pt").length === want,
         fig.svg.querySelectorAll(".pt").length);
    }
  }

  function testFlips() {
    var fig = figure("flips");
    DT.useScene(fig.sceneId);
    var flips = 0, m0 = DT.sceneMesh(), ids = {};
    for (var v = 0; v < m0.ids.length; v++) ids[m0.ids[v]] = true;
    var labels = Array.prototype.map.call(fig.svg.querySelectorAll(".label"), function (e) { return e.textContent; });
    ok("2.3.6 every vertex is labelled", labels.length === Object.keys(ids).length &&
       Object.keys(ids).every(function (id) { return labels.indexOf("p" + id) >= 0; }), labels.join(" "));
    ok("2.3.6 some flips to do", fig.total > 0, fig.total);
    while (!fig.finished) {
      fig.click();
      if (!fig.finished) {
        flips++;
        ok("2.3.6 flip " + flips + " drawn", fig.svg.querySelectorAll(".old").length === 1 &&
           fig.svg.querySelectorAll(".new").length === 1, "");
      }
      if (flips > 10000) break;
    }
    ok("2.3.6 flips replayed = recoverDelaunay's", flips === fig.total, flips + " vs " + fig.total);
    ok("2.3.6 the last frame draws no super face", fig.svg.querySelector(".super").getAttribute("d") === "", "");
    DT.useScene(fig.sceneId);
    var m = DT.sceneMesh(), real = 0;
    for (var t = 0; t < m.count; t++)
      if (m.ids[3 * t] >= 0 && m.ids[3 * t + 1] >= 0 && m.ids[3 * t + 2] >= 0) real++;
    var fast = DT.triangulate(new Float64Array(fig.xy), true).length / 3;
    ok("2.3.6 recovered DT(S) has the fast kernel's triangle count", real === fast, real + " vs " + fast);
  }

  // ---- the page as the book builds it: fallback gone, skip links, names and roles ----------
  function testPage(figs) {
    ok("page: loader.js built the five figures", figs.length === 5, figs.length);
    var fallback = Array.prototype.filter.call(document.querySelectorAll(".dt-live"), function (n) {
      return n.textContent.indexOf("needs JavaScript") >= 0;
    });
    ok("page: the fallback sentence is gone once the figures load", fallback.length === 0, fallback.length + " left");
    var skips = document.querySelectorAll(".dt-skip a");
    ok("page: a skip link to each figure, first in the page", skips.length === 5 &&
       document.body.firstElementChild.classList.contains("dt-skip") &&
       Array.prototype.every.call(skips, function (a, i) { return a.getAttribute("href") === "#" + figs[i].svg.closest(".dt-live").id; }),
       skips.length);
    // Following the skip link puts the focus on the figure's drawing: the next key moves it.
    skips[0].dispatchEvent(new MouseEvent("click", { bubbles: true, cancelable: true }));
    ok("page: the skip link focuses the drawing", document.activeElement === figs[0].svg,
       document.activeElement && document.activeElement.outerHTML.slice(0, 80));
  }

  // ---- the GIF's pause: paused from the start iff reduced motion is asked; the button toggles --
  function testGif() {
    var reduce = window.matchMedia("(prefers-reduced-motion: reduce)").matches;
    var img = document.querySelector("img"), btn = document.querySelector(".dt-gif-pause"),
        still = document.querySelector(".dt-gif-still");
    function paused() { return img.style.display === "none" && still.style.display === "" && btn.getAttribute("aria-pressed") === "true"; }
    ok("gif: a pause button; " + (reduce ? "reduced motion: paused from the start" : "playing from the start"),
       btn && paused() === reduce, btn ? btn.textContent : "no button");
    if (!btn) return;
    btn.dispatchEvent(new MouseEvent("click", { bubbles: true }));
    ok("gif: the button " + (reduce ? "plays" : "pauses") + " it", paused() !== reduce, btn.textContent);
    if (!paused()) btn.dispatchEvent(new MouseEvent("click", { bubbles: true }));
    var px = still.getContext("2d").getImageData(0, 0, 1, 1).data;
    ok("gif: paused, a frame of it stays in view", paused() && px[3] === 255 && (px[2] === 143 || px[0] === 214),
       Array.prototype.join.call(px, ","));
  }

  // ---- a tap where the finger is: the drawing's scaled box, not its viewBox units ----------
  function tap(node, type, cx, cy) {
    node.dispatchEvent(new PointerEvent(type, { bubbles: true, clientX: cx, clientY: cy, pointerId: 2,
                                                isPrimary: true, pointerType: "touch", buttons: type === "pointerup" ? 0 : 1 }));
  }
  function testTap() {
    var w = window.innerWidth, fig = figure("cavity");
    if (window.parent !== window) ok("tap: the frame is a phone's width, 390 px", w === 390, w);
    fig.setSize(100);
    fig.svg.scrollIntoView();
    var r = fig.svg.getBoundingClientRect();
    if (w < 600) ok("tap at " + w + " px: the drawing is scaled to the page", r.width < 560, r.width);
    [[0.75, 0.75], [0.25, 0.4], [0.6, 0.1]].forEach(function (q) {
      r = fig.svg.getBoundingClientRect();
      var cx = r.left + q[0] * r.width, cy = r.top + q[1] * r.height;
      tap(fig.svg, "pointerdown", cx, cy);
      tap(fig.svg, "pointerup", cx, cy);
      var p = fig.svg.querySelector(".p").getBoundingClientRect();
      var d = Math.hypot(p.left + p.width / 2 - cx, p.top + p.height / 2 - cy);
      ok("tap at " + w + " px, " + q + " of the drawing: p under the finger", d <= 2, d.toFixed(1) + " px away");
    });
    // The predicate map's cursor too (a canvas: its box on screen scaled to the cells).
    var map = figure("predicates");
    map.canvas.scrollIntoView();
    r = map.canvas.getBoundingClientRect();
    var cx = r.left + 0.75 * r.width, cy = r.top + 0.75 * r.height;
    tap(map.canvas, "pointerdown", cx, cy);
    var cw = r.width / 256, ccx = r.left + (map.cursor[0] + 0.5) * cw, ccy = r.top + (255 - map.cursor[1] + 0.5) * cw;
    ok("tap at " + w + " px on the map: its cursor cell under the finger", Math.hypot(ccx - cx, ccy - cy) <= 2,
       "cell " + map.cursor + " centre " + Math.hypot(ccx - cx, ccy - cy).toFixed(1) + " px away");
  }

  // ---- keys alone: focus each drawing, press keys, check what moved and what was said -------
  function key(node, k, shift) {
    node.focus();
    document.activeElement.dispatchEvent(new KeyboardEvent("keydown", { key: k, shiftKey: !!shift, bubbles: true, cancelable: true }));
  }
  function focusable(tag, node) {
    node.focus();
    ok(tag + " drawing takes the focus, with a role and a name", document.activeElement === node &&
       node.getAttribute("tabindex") === "0" && !!node.getAttribute("role") && !!node.getAttribute("aria-label"), node.outerHTML.slice(0, 120));
  }
  function testKeys() {
    var c = figure("cavity");
    c.setSize(100);
    c.setShow("both");
    focusable("keys 2.1/2.4:", c.svg);
    var b = c.view.box, wx = b[2] - b[0], wy = b[3] - b[1];
    [["ArrowRight", false, 0.01, 0], ["ArrowRight", true, 0.1, 0], ["ArrowUp", false, 0, 0.01],
     ["ArrowDown", true, 0, -0.1], ["ArrowLeft", false, -0.01, 0]].forEach(function (k) {
      var p = c.report.p, before = c.info.textContent;
      key(c.svg, k[0], k[1]);
      var q = c.report.p;
      ok("keys 2.1/2.4: " + (k[1] ? "Shift+" : "") + k[0] + " moves p by " + Math.abs(k[2] + k[3]) * 100 + " % of the view",
         Math.abs(q[0] - p[0] - k[2] * wx) < 1e-12 && Math.abs(q[1] - p[1] - k[3] * wy) < 1e-12 &&
         c.info.textContent !== before && c.counts().cavity === c.report.cavityFinite,
         [(q[0] - p[0]) / wx, (q[1] - p[1]) / wy, c.info.textContent !== before, c.counts().cavity,
          c.report.cavityFinite].join(" "));
    });
    var shown = c.svg.parentNode.querySelector(".dt-show").value;
    key(c.svg, "Enter");
    ok("keys 2.1/2.4: Enter shows the next view", c.svg.parentNode.querySelector(".dt-show").value !== shown, shown);

    var bw = figure("bowyer");
    bw.start();
    focusable("keys 2.5:", bw.svg);
    key(bw.svg, "Enter");
    key(bw.svg, " ");
    ok("keys 2.5: Enter and Space insert one point each", bw.steps === 2 && bw.counts().cavity === bw.report.cavityFinite &&
       bw.info.textContent.indexOf("Point 2 of 9 inserted") === 0, bw.steps + ": " + bw.info.textContent);

    var m = figure("predicates");
    m.set("exact", 0);
    m.home();
    focusable("keys 2.7:", m.canvas);
    m.moveCursor(10, 10);
    key(m.canvas, "ArrowRight");
    key(m.canvas, "ArrowUp", true);
    ok("keys 2.7: arrows move the cursor (Shift: 16 cells)", m.cursor[0] === 11 && m.cursor[1] === 26,
       String(m.cursor));
    ok("keys 2.7: the cursor's line says its cell", m.cellLine.textContent.indexOf("Cell (11, 26)") === 0,
       m.cellLine.textContent);
    key(m.canvas, "-");
    ok("keys 2.7: - zooms out about the cursor", m.step === 2 * Math.pow(2, -53) &&
       m.x0 + 11 * m.step === 0.5 + 11 * Math.pow(2, -53), m.step);
    key(m.canvas, "+");
    var mode = m.canvas.parentNode.querySelector(".dt-what").value;
    key(m.canvas, "Enter");
    ok("keys 2.7: + zooms back, Enter shows the next map", m.step === Math.pow(2, -53) &&
       m.canvas.parentNode.querySelector(".dt-what").value !== mode, m.step);
    m.home();

    var h = figure("hilbert");
    h.set("hilbert", 3, 1);
    focusable("keys 2.11:", h.svg);
    key(h.svg, "ArrowRight");
    ok("keys 2.11: Right deepens the curve", h.info.textContent.indexOf("depth 4") >= 0, h.info.textContent);
    key(h.svg, "Enter");
    key(h.svg, "ArrowUp");
    ok("keys 2.12: Enter shows the BRIO rounds, Up one more round", h.info.textContent.indexOf("BRIO") === 0 &&
       h.info.textContent.indexOf("Rounds 1 to 2 drawn") >= 0, h.info.textContent);
    h.set("hilbert", 3);

    var fl = figure("flips");
    fl.start();
    focusable("keys 2.3.6:", fl.svg);
    key(fl.svg, "Enter");
    key(fl.svg, " ");
    ok("keys 2.3.6: Enter and Space do one flip each", fl.done === 2 && fl.info.textContent.indexOf("Flip 2 of") === 0,
       fl.done + ": " + fl.info.textContent);
  }

  // ---- axe-core on the page, after every figure was driven: no WCAG 2.1 A/AA violation ------
  function testAxe() {
    return axe.run(document, { runOnly: { type: "tag", values: ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"] } })
      .then(function (res) {
        ok("axe-core: no WCAG 2.1 A/AA violation at " + window.innerWidth + " px", res.violations.length === 0,
           res.violations.map(function (v) {
             return v.id + " (" + v.nodes.length + ": " + v.nodes.slice(0, 2).map(function (n) { return n.target.join(" "); }).join(", ") + ")";
           }).join("; "));
        ok("axe-core ran its rules", res.passes.length > 10, res.passes.length);
      }, function (e) { ok("axe-core runs", false, String(e)); });
  }

  document.addEventListener("dt-live-mounted", function (ev) {
    var figs = ev.detail;
    attempt("page", function () { testPage(figs); });
    attempt("gif", testGif);
    attempt("tap", testTap);
    attempt("native cases", testCases);
    attempt("2.1/2.4 cavity figure", testCavity);
    attempt("2.5 Bowyer-Watson figure", testBowyer);
    attempt("2.7/2.8 predicate maps", testPredicates);
    attempt("2.11/2.12 Hilbert figure", testHilbert);
    attempt("2.3.6 flips figure", testFlips);
    attempt("keys", testKeys);
    testAxe().then(finish, finish);
  });
  // A module that does not load sends no mount event: the verdict stays NOT RUN, which
  // run_browser_test.sh reports as a failure. (No timer here: under virtual time a timer can
  // fire while the module is still being compiled.)
})();
