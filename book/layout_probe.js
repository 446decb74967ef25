// The book's layout, measured in a real browser (book/layout_check.sh runs it in headless
// Chromium). The harness page lists the pages and the window widths; each page is loaded in
// an iframe of that width, MathJax is let finish (formulas change widths), and every table,
// image, code block, caption and live figure of the text column is measured:
//   - wider than the column (its box ends past the column's content edge), or
//   - wider than itself (scrollWidth > clientWidth: a scroll bar inside the text, or a cut-off
//     caption), or
//   - a page that scrolls sideways as a whole.
// One line per defect, naming the page, the width, the element and the overshoot in pixels;
// the last line is "LAYOUT <n> defects in <pages> page loads". The harness writes them into
// <pre id="layout-result">, which --dump-dom prints.
(function () {
  'use strict';
  var cfg = window.LAYOUT_CHECK;  // {pages: [...], widths: [...], height: N, timeoutMs: N}
  var out = document.getElementById('layout-result');
  var frame = document.getElementById('layout-frame');
  var lines = [], jobs = [], loads = 0;
  cfg.widths.forEach(function (w) { cfg.pages.forEach(function (p) { jobs.push([p, w]); }); });

  function describe(el) {
    var s = el.tagName.toLowerCase();
    if (el.id) s += '#' + el.id;
    if (el.className && typeof el.className === 'string') s += '.' + el.className.trim().split(/\s+/).join('.');
    if (el.tagName === 'IMG') s += ' src=' + (el.getAttribute('src') || '');
    var heading = el.tagName === 'TABLE' ? el.querySelector('th') : null;
    var text = (heading || el).textContent || '';
    text = text.replace(/\s+/g, ' ').trim().slice(0, 48);
    if (text) s += ' "' + text + '"';
    return s;
  }

  function measure(page, width, win, doc) {
    var found = [];
    var col = doc.querySelector('div.contents') || doc.body;
    var cs = win.getComputedStyle(col);
    var cr = col.getBoundingClientRect();
    var left = cr.left + parseFloat(cs.paddingLeft), right = cr.right - parseFloat(cs.paddingRight);
    var seen = [];
    function covered(el) {
      for (var i = 0; i < seen.length; ++i) if (seen[i].contains(el) || el.contains(seen[i])) return true;
      return false;
    }
    // First the things themselves: an image, a table, a code block or a formula whose box ends
    // past the column.
    var things = 'img, table, pre, div.fragment, svg, canvas, iframe, object, video, ' +
                 '.MathJax_Display, div.live';
    col.querySelectorAll(things).forEach(function (el) {
      if (covered(el)) return;
      if (el.parentElement && el.parentElement.closest('svg')) return;
      var r = el.getBoundingClientRect();
      if (r.width === 0 && r.height === 0) return;  // not displayed
      var over = Math.max(r.right - right, left - r.left);
      if (over > 1) {
        found.push(page + ' @' + width + 'px: ' + describe(el) + ' is ' + Math.round(r.width) +
                   ' px wide, ' + Math.round(over) + ' px past the text column (' +
                   Math.round(right - left) + ' px)');
        seen.push(el);
      }
    });
    // Then every box of the text whose content is wider than the box: a scroll bar inside the
    // text (a table the style lets scroll), or a caption cut off.
    col.querySelectorAll('*').forEach(function (el) {
      if (covered(el) || el.clientWidth === 0) return;
      if (el.parentElement && el.parentElement.closest('svg')) return;
      var ox = win.getComputedStyle(el).overflowX;
      var clips = ox === 'auto' || ox === 'scroll' || ox === 'hidden' || ox === 'clip';
      var caption = /caption/i.test(el.tagName + ' ' + el.className);
      if (!(clips || caption) || el.scrollWidth <= el.clientWidth + 1) return;
      found.push(page + ' @' + width + 'px: ' + describe(el) + (caption ? ' is cut off' : ' scrolls sideways') +
                 ' (' + el.scrollWidth + ' px of content in ' + el.clientWidth + ' px)');
      seen.push(el);
    });
    // The page itself, or Doxygen's content pane, scrolling sideways.
    [doc.documentElement, doc.getElementById('doc-content')].forEach(function (el) {
      if (el && el.scrollWidth > el.clientWidth + 1)
        found.push(page + ' @' + width + 'px: the page scrolls sideways (' + el.scrollWidth +
                   ' px of content in a ' + el.clientWidth + ' px window)');
    });
    return found;
  }

  function next() {
    if (!jobs.length) {
      lines.push('LAYOUT ' + (lines.length) + ' defects in ' + loads + ' page loads');
      out.textContent = lines.join('\n');
      return;
    }
    var job = jobs.shift(), url = job[0], width = job[1];
    var page = decodeURIComponent(url.replace(/^.*\//, ''));
    var done = false;
    var timer = setTimeout(function () {
      if (done) return;
      done = true;
      lines.push(page + ' @' + width + 'px: did not finish loading in ' + cfg.timeoutMs + ' ms');
      next();
    }, cfg.timeoutMs);
    frame.style.width = width + 'px';
    frame.style.height = cfg.height + 'px';
    frame.onload = function () {
      var win = frame.contentWindow, doc = frame.contentDocument;
      function finish() {
        if (done) return;
        done = true;
        clearTimeout(timer);
        ++loads;
        // Let Doxygen's resize script set the content pane's size first (a timer, not
        // requestAnimationFrame: headless Chromium under a virtual time budget may never run a
        // frame for a page nobody looks at).
        setTimeout(function () {
          try { lines = lines.concat(measure(page, width, win, doc)); }
          catch (e) { lines.push(page + ' @' + width + 'px: the probe failed: ' + e); }
          next();
        }, 100);
      }
      if (win.MathJax && win.MathJax.Hub && win.MathJax.Hub.Queue) win.MathJax.Hub.Queue(finish);
      else finish();
    };
    frame.src = url;
  }
  next();
})();
