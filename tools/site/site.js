/* site.js: the book's theme switch and search (tools/site/build.sh).
 * The search index (search-index.js) holds every section of every page:
 * its page, title, anchor and text. A query matches a section holding
 * every one of its words; sections whose title matches come first. */
(function () {
  "use strict";
  var root = document.body.getAttribute("data-root") || "";

  var theme = document.getElementById("theme");
  theme.addEventListener("click", function () {
    var now = document.documentElement.getAttribute("data-theme") === "dark" ? "light" : "dark";
    document.documentElement.setAttribute("data-theme", now);
    try { localStorage.setItem("theme", now); } catch (e) {}
  });

  var input = document.getElementById("search"), box = document.getElementById("results");
  var index = window.SEARCH_INDEX || [];

  function escapeHtml(s) {
    return s.replace(/[&<>"]/g, function (c) {
      return {"&": "&amp;", "<": "&lt;", ">": "&gt;", "\"": "&quot;"}[c];
    });
  }

  function snippet(text, word) {
    var i = text.toLowerCase().indexOf(word), from = Math.max(0, i - 60);
    var s = (from > 0 ? "…" : "") + text.substr(from, 160) + (from + 160 < text.length ? "…" : "");
    var out = escapeHtml(s), w = escapeHtml(word);
    return w ? out.replace(new RegExp(w.replace(/[.*+?^${}()|[\]\\]/g, "\\$&"), "ig"),
                           function (m) { return "<mark>" + m + "</mark>"; }) : out;
  }

  function search(query) {
    var words = query.toLowerCase().split(/\s+/).filter(Boolean);
    if (!words.length) return [];
    var hits = [];
    index.forEach(function (s) {
      var title = s.title.toLowerCase(), all = title + " " + s.text.toLowerCase();
      if (words.every(function (w) { return all.indexOf(w) >= 0; }))
        hits.push({s: s, score: words.every(function (w) { return title.indexOf(w) >= 0; }) ? 0 : 1});
    });
    hits.sort(function (a, b) { return a.score - b.score; });
    return hits.slice(0, 30);
  }

  function show() {
    var q = input.value.trim(), hits = search(q);
    if (!q) { box.hidden = true; return; }
    var first = q.toLowerCase().split(/\s+/)[0];
    box.innerHTML = hits.length ? hits.map(function (h) {
      var url = root + h.s.page + (h.s.id ? "#" + h.s.id : "");
      return "<a href=\"" + escapeHtml(url) + "\"><span class=\"where\">" + escapeHtml(h.s.page) +
             "</span><br>" + escapeHtml(h.s.title) + "<br><span class=\"snippet\">" +
             snippet(h.s.text, first) + "</span></a>";
    }).join("") : "<p>No section holds every word of “" + escapeHtml(q) + "”.</p>";
    box.hidden = false;
  }

  input.addEventListener("input", show);
  input.addEventListener("keydown", function (e) {
    if (e.key === "Escape") { input.value = ""; box.hidden = true; }
    if (e.key === "Enter") { var a = box.querySelector("a"); if (a) a.click(); }
  });
  document.addEventListener("keydown", function (e) {
    if (e.key === "/" && document.activeElement !== input) { e.preventDefault(); input.focus(); }
  });
  document.addEventListener("click", function (e) {
    if (!box.contains(e.target) && e.target !== input) box.hidden = true;
  });
})();
