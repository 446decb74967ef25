// Loads the live figures into a book page: style.js, dt_wasm.js (the library in WebAssembly,
// embedded in the file), dt.js and live.js, from the directory of this script, one after the
// other (plain <script> elements work from file:// with no server), then builds every
// <div class="dt-live" data-figure="..."> of the page. Without them the static figure stays.
(function () {
  var me = document.currentScript;
  var base = me ? me.src.replace(/[^\/]*$/, "") : "live/";
  var files = ["style.js", "dt_wasm.js", "dt.js", "live.js"];
  function fail(what) {
    document.querySelectorAll(".dt-live").forEach(function (n) {
      n.textContent = "The live figure is not available (" + what + "): scripts/main.sh builds it " +
        "into the book's live/ directory when emscripten is installed.";
    });
  }
  function next(i) {
    if (i === files.length) {
      DT.ready.then(function () { DTLive.mountAll(); }, function (e) { fail(String(e)); });
      return;
    }
    var s = document.createElement("script");
    s.src = base + files[i];
    s.onload = function () { next(i + 1); };
    s.onerror = function () { fail(files[i] + " missing"); };
    document.head.appendChild(s);
  }
  if (document.readyState === "loading")
    document.addEventListener("DOMContentLoaded", function () { next(0); });
  else next(0);
})();
