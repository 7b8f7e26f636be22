// What a reader would see go wrong on a page, found in the page itself by headless Chromium (tests/cli/
// report_browser.sh injects this first in a page's <head>). It records every error event (scripts and resources alike,
// caught in the capture phase) and every console.error, and once the page has loaded it looks for:
//   - an <img> not shown (naturalWidth 0) or an <object> without its content;
//   - a figure without its plot, or one drawn too small; a plot point with gnuplot's script hover handler;
//   - a link to an anchor the page lacks;
//   - a table wider than its container with no scrolling box around it (it would be cut at the page's edge);
//   - a number in a table cell broken over two lines (1.2e-<break>05), unless window.vsswSkipNumbers is set before
//     this script (the documentation site, whose tables are prose: the pages that vssw writes are checked).
// The verdict goes into window.vsswVerdict and a <pre> at the end of the body ("VSSW-CHECK OK ..." or
// "VSSW-CHECK FAIL" and one line per problem), which --dump-dom prints or a harness page reads.
(function () {
  var problems = [];
  window.addEventListener("error", function (e) {
    var t = e.target;
    var where = t && t !== window ? t.getAttribute && (t.getAttribute("src") || t.getAttribute("href") ||
                                                      t.getAttribute("data")) : null;
    problems.push(where ? "did not load: " + where : "script error: " + e.message);
  }, true);
  var consoleError = console.error;
  console.error = function () {
    problems.push("console error: " + Array.prototype.join.call(arguments, " ").slice(0, 120));
    return consoleError.apply(console, arguments);
  };

  // The nearest ancestor that scrolls horizontally, or null.
  function scroller(el) {
    for (var a = el.parentElement; a && a !== document.documentElement; a = a.parentElement) {
      var ox = getComputedStyle(a).overflowX;
      if (ox === "auto" || ox === "scroll") return a;
    }
    return null;
  }

  function tables(p) {
    document.querySelectorAll("table").forEach(function (t, i) {
      var width = t.getBoundingClientRect().width, room = t.parentElement.getBoundingClientRect().width;
      if (width > room + 1 && !scroller(t))
        p.push("table " + i + " wider than its container (" + Math.round(width) + " > " + Math.round(room) +
               " px) and not in a scrolling box: " + t.textContent.replace(/\s+/g, " ").trim().slice(0, 60));
    });
    if (window.vsswSkipNumbers) return;
    // A number (four characters or more: 0.25, 1e-6, -1.5e+03), drawn on more than one line; the first few named.
    var number = /[-+]?\d+(\.\d+)?(e[-+]?\d+)?/gi, broken = 0;
    document.querySelectorAll("td, th").forEach(function (cell) {
      var walker = document.createTreeWalker(cell, NodeFilter.SHOW_TEXT), node;
      while ((node = walker.nextNode())) {
        var m;
        number.lastIndex = 0;
        while ((m = number.exec(node.data))) {
          if (m[0].length < 4) continue;
          var r = document.createRange();
          r.setStart(node, m.index);
          r.setEnd(node, m.index + m[0].length);
          var lines = {};
          Array.prototype.forEach.call(r.getClientRects(), function (b) {
            if (b.width > 0) lines[Math.round(b.top)] = 1;
          });
          if (Object.keys(lines).length > 1) {
            if (++broken <= 3) p.push("number broken over lines in a table cell: " + m[0]);
            return;
          }
        }
      }
    });
  }

  function figures(p) {
    document.querySelectorAll("img").forEach(function (img) {
      if (!img.complete || img.naturalWidth === 0) p.push("image not shown: " + img.getAttribute("src"));
    });
    document.querySelectorAll("object").forEach(function (o) {
      var r = o.getBoundingClientRect();
      if (!o.contentDocument || r.width === 0 || r.height === 0) p.push("object not shown: " + o.getAttribute("data"));
    });
    document.querySelectorAll("[onmousemove]").forEach(function (g) {
      p.push("script hover handler: " + g.getAttribute("onmousemove").slice(0, 60));
    });
    var plots = 0;
    document.querySelectorAll("figure").forEach(function (f, i) {
      var svg = f.querySelector("svg"), r = svg ? svg.getBoundingClientRect() : null;
      if (!svg && !f.querySelector("img, object"))
        p.push("figure " + i + " holds no plot: " + f.textContent.slice(0, 80));
      else if (svg && (r.width < 300 || r.height < 100))
        p.push("figure " + i + " drawn at " + r.width + " x " + r.height);
      else plots++;
    });
    return plots;
  }

  window.addEventListener("load", function () {
    var p = problems.slice();
    var plots = figures(p);
    tables(p);
    document.querySelectorAll("a[href^=\"#\"]").forEach(function (a) {
      var id = decodeURIComponent(a.getAttribute("href").slice(1));
      if (id && !document.getElementById(id)) p.push("link without its anchor: " + a.getAttribute("href"));
    });
    var hovers = 0;
    document.querySelectorAll("figure svg g > title").forEach(function (t) { if (t.textContent.trim()) hovers++; });
    window.vsswVerdict = p.length ? "VSSW-CHECK FAIL\n" + p.join("\n")
                                  : "VSSW-CHECK OK hovers=" + hovers + " plots=" + plots;
    var out = document.createElement("pre");
    out.textContent = window.vsswVerdict;
    document.body.appendChild(out);
  });
})();
