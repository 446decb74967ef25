// Accessibility, measured in a real browser (book/axe_check.sh runs it in headless Chromium):
// each page is loaded in an iframe 1280 px wide, MathJax is let finish, axe-core is put into
// the page and run with the WCAG 2.0/2.1 A and AA rules. One line per failing element (page,
// rule, impact, the element's selector and axe's summary); the last line is
// "AXE <n> violations in <pages> pages". The harness writes them into <pre id="axe-result">,
// which --dump-dom prints.
(function () {
  'use strict';
  var cfg = window.AXE_CHECK;  // {pages: [...], axe: URL of axe.min.js, width: N, timeoutMs: N}
  var out = document.getElementById('axe-result');
  var frame = document.getElementById('axe-frame');
  var lines = [], jobs = cfg.pages.slice(), pages = 0, count = 0;

  function next() {
    if (!jobs.length) {
      lines.push('AXE ' + count + ' violations in ' + pages + ' pages');
      out.textContent = lines.join('\n');
      return;
    }
    var url = jobs.shift();
    var page = decodeURIComponent(url.replace(/^.*\//, ''));
    var done = false;
    function fail(msg) {
      if (done) return;
      done = true;
      ++count;
      lines.push(page + ': ' + msg);
      next();
    }
    var timer = setTimeout(function () { fail('did not finish in ' + cfg.timeoutMs + ' ms'); }, cfg.timeoutMs);
    frame.style.width = cfg.width + 'px';
    frame.style.height = '900px';
    frame.onload = function () {
      var win = frame.contentWindow, doc = frame.contentDocument;
      function run() {
        var s = doc.createElement('script');
        s.src = cfg.axe;
        s.onerror = function () { clearTimeout(timer); fail('axe-core could not be loaded from ' + cfg.axe); };
        s.onload = function () {
          win.axe.run(doc, {runOnly: {type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa']},
                            resultTypes: ['violations']})
            .then(function (r) {
              if (done) return;
              done = true;
              clearTimeout(timer);
              ++pages;
              r.violations.forEach(function (v) {
                v.nodes.forEach(function (n) {
                  ++count;
                  var why = (n.failureSummary || '').replace(/\s+/g, ' ').slice(0, 160);
                  lines.push(page + ': ' + v.id + ' (' + (v.impact || '-') + ') ' + n.target.join(' ') + ': ' + why);
                });
              });
              next();
            }, function (e) { clearTimeout(timer); fail('axe failed: ' + e); });
        };
        doc.head.appendChild(s);
      }
      // Formulas change the page (MathJax adds elements): measure what a reader gets.
      if (win.MathJax && win.MathJax.Hub && win.MathJax.Hub.Queue) win.MathJax.Hub.Queue(function () { setTimeout(run, 100); });
      else setTimeout(run, 100);
    };
    frame.src = url;
  }
  next();
})();
