// Loads the live figures into a book page: style.js, dt_wasm.js (the library in WebAssembly,
// embedded in the file), dt.js and live.js, from the directory of this script, one after the
// other (plain <script> elements work from file:// with no server), then builds every
// <div class="dt-live" data-figure="..."> of the page. Without them the static figure stays.
// It also gives the page what the figures need to be usable by everyone: a skip link to each
// figure at the top of the page, and a pause button for each animated GIF (paused from the
// start when the reader asks for reduced motion).
(function () {
  var me = document.currentScript;
  var base = me ? me.src.replace(/[^\/]*$/, "") : "live/";
  // data-wasm on the script element names another build of the module (the test's planted one).
  var files = ["style.js", (me && me.getAttribute("data-wasm")) || "dt_wasm.js", "dt.js", "live.js"];
  function fail(what) {
    document.querySelectorAll(".dt-live").forEach(function (n) {
      n.textContent = "The live figure is not available (" + what + "): scripts/main.sh builds it " +
        "into the book's live/ directory when emscripten is installed.";
    });
  }
  // One link per live figure, first in the page, shown when it has the focus (a keyboard
  // reader skips the navigation and the text before the figure).
  function skipLinks() {
    var nodes = document.querySelectorAll(".dt-live");
    if (!nodes.length || document.querySelector(".dt-skip")) return;
    var nav = document.createElement("nav");
    nav.className = "dt-skip";
    nav.setAttribute("aria-label", "Skip links to the live figures");
    nodes.forEach(function (n, i) {
      if (!n.id) n.id = "live-figure-" + (i + 1);
      var a = document.createElement("a");
      a.href = "#" + n.id;
      a.textContent = "Skip to the live figure" + (nodes.length > 1 ? " " + (i + 1) : "");
      a.addEventListener("click", function (ev) {
        // Into the figure's drawing itself, so the next key already moves it.
        var target = n.querySelector("[tabindex]") || n;
        if (target === n) n.setAttribute("tabindex", "-1");
        target.focus();
        ev.preventDefault();
      });
      nav.appendChild(a);
    });
    document.body.insertBefore(nav, document.body.firstChild);
  }
  // A pause button under each animated GIF: pausing draws the frame shown into a canvas put in
  // its place; playing shows the GIF again. Reduced motion: paused from the start.
  function gifPauses() {
    var reduce = window.matchMedia && window.matchMedia("(prefers-reduced-motion: reduce)").matches;
    document.querySelectorAll("img").forEach(function (img) {
      if (!/\.gif$/i.test(img.getAttribute("src") || "")) return;
      var btn = document.createElement("button"), still = document.createElement("canvas");
      btn.type = "button";
      btn.className = "dt-gif-pause";
      still.className = "dt-gif-still";
      still.setAttribute("role", "img");
      still.setAttribute("aria-label", (img.getAttribute("alt") || "animation") + " (paused)");
      still.style.display = "none";
      img.parentNode.insertBefore(still, img.nextSibling);
      still.parentNode.insertBefore(btn, still.nextSibling);
      function set(paused) {
        if (paused) {
          still.width = img.naturalWidth;
          still.height = img.naturalHeight;
          still.style.width = img.getBoundingClientRect().width + "px";
          still.getContext("2d").drawImage(img, 0, 0);
        }
        img.style.display = paused ? "none" : "";
        still.style.display = paused ? "" : "none";
        btn.textContent = paused ? "play the animation" : "pause the animation";
        btn.setAttribute("aria-pressed", paused ? "true" : "false");
        btn.dataset.paused = paused ? "1" : "";
      }
      btn.addEventListener("click", function () { set(!btn.dataset.paused); });
      if (img.complete) set(reduce);
      else img.addEventListener("load", function () { set(reduce); });
    });
  }
  function next(i) {
    if (i === files.length) {
      DT.ready.then(function () {
        var figs = DTLive.mountAll();
        // For a script that waits for the figures (the browser test).
        document.dispatchEvent(new CustomEvent("dt-live-mounted", { detail: figs }));
      }, function (e) { fail(String(e)); });
      return;
    }
    var s = document.createElement("script");
    s.src = base + files[i];
    s.onload = function () { next(i + 1); };
    s.onerror = function () { fail(files[i] + " missing"); };
    document.head.appendChild(s);
  }
  function start() {
    skipLinks();
    gifPauses();
    next(0);
  }
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
