/* site.js: the book's theme switch, search and Run buttons (tools/site/build.sh).
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
  /* "/" goes to the search, unless it is typed into a field (a Run
   * command line: build/bin/NN --out out/x.png). */
  document.addEventListener("keydown", function (e) {
    var a = document.activeElement;
    var typing = a && (/^(INPUT|TEXTAREA|SELECT)$/.test(a.tagName) || a.isContentEditable);
    if (e.key === "/" && !typing) { e.preventDefault(); input.focus(); }
  });
  document.addEventListener("click", function (e) {
    if (!box.contains(e.target) && e.target !== input) box.hidden = true;
  });

  /* Run it here: each .run widget (links.lua) runs its command line in the
   * lesson's browser build, on the page's worker (worker.js), and shows what
   * it printed and the pictures it wrote. A widget keeps the last result in
   * its .result (the site's test reads it) and says data-state="done". */
  var worker = null, calls = 0, waiting = {};
  function run(widget) {
    var words = widget.querySelector(".run-cmd").value.trim().split(/\s+/);
    var m = /^(?:\.\/)?build\/bin\/(\d\d_\w+)$/.exec(words[0] || "");
    var out = widget.querySelector(".run-out"), pics = widget.querySelector(".run-pictures");
    widget.querySelector(".run-result").hidden = false;
    pics.innerHTML = "";
    if (!m) {
      out.textContent = "In the page, a command is build/bin/NN_name and its arguments.";
      widget.setAttribute("data-state", "done");
      return;
    }
    widget.setAttribute("data-state", "running");
    out.textContent = "running " + m[1] + " in the page...";
    ask(m[1], words.slice(1), function (r) { showResult(widget, r); });
  }
  /* The lesson on args, on the page's one worker; then done(result), which
   * says {error} when the worker cannot start or stops: a page opened as a
   * file (file://) may not start one. */
  function ask(lesson, args, done) {
    if (!worker) {
      try {
        worker = new Worker(root + "worker.js");
      } catch (e) {
        done({error: location.protocol === "file:"
          ? "a page opened as a file cannot run the lessons: serve the book " +
            "(make site-serve) and read it at http://127.0.0.1:8000/"
          : String(e && e.message || e)});
        return;
      }
      worker.onmessage = function (e) {
        var d = waiting[e.data.id];
        delete waiting[e.data.id];
        if (d) d(e.data);
      };
      worker.onerror = function (e) {
        e.preventDefault();
        var stopped = waiting;
        waiting = {};
        worker = null;
        Object.keys(stopped).forEach(function (id) {
          stopped[id]({error: "the page's worker stopped: " + (e.message || "it could not load")});
        });
      };
    }
    var id = ++calls;
    waiting[id] = done;
    worker.postMessage({id: id, lesson: lesson, args: args});
  }
  function showResult(widget, r) {
    var out = widget.querySelector(".run-out"), pics = widget.querySelector(".run-pictures");
    widget.result = r;
    if (r.error) {
      out.textContent = "could not run it here: " + r.error;
    } else {
      out.textContent = r.printed + (r.status ? "[exit status " + r.status + "]\n" : "");
      r.written.forEach(function (f) {
        if (!/\.png$/.test(f[0])) return;
        var fig = document.createElement("figure"), img = document.createElement("img");
        var cap = document.createElement("figcaption");
        img.src = URL.createObjectURL(new Blob([f[1]], {type: "image/png"}));
        img.alt = "what the run wrote to " + f[0];
        cap.textContent = f[0];
        fig.appendChild(img);
        fig.appendChild(cap);
        pics.appendChild(fig);
      });
    }
    widget.setAttribute("data-state", "done");
  }
  /* A live figure (links.lua): the lesson's --steps pictures on a slider, and
   * its --trace of the pixel clicked. It says data-state="ready" once drawn
   * and "traced" after a trace (the site's test waits for them). */
  var FIGURE_W = 320, FIGURE_H = 240;
  Array.prototype.forEach.call(document.querySelectorAll('.figure-live[data-kind="flags"]'), flagsFigure);
  Array.prototype.forEach.call(document.querySelectorAll('.figure-live[data-kind="steps"]'), function (fig) {
    var lesson = fig.getAttribute("data-lesson");
    var extra = (fig.getAttribute("data-args") || "").split(/\s+/).filter(Boolean);
    var size = ["--width", String(FIGURE_W), "--height", String(FIGURE_H)].concat(extra);
    var start = fig.querySelector(".figure-start"), body = fig.querySelector(".figure-body");
    var slider = fig.querySelector(".figure-slider"), label = fig.querySelector(".figure-step");
    var trace = fig.querySelector(".figure-trace"), img = null; /* made once drawn */
    var steps = [];
    function showStep() {
      var k = Number(slider.value);
      img.src = steps[k];
      label.textContent = k === 0 ? " the buffer cleared, no face drawn"
                                  : " after " + k + " face" + (k === 1 ? "" : "s");
    }
    start.addEventListener("click", function () {
      start.disabled = true;
      start.textContent = "drawing in the page...";
      ask(lesson, size.concat(["--steps", "out/figure-steps", "--out", "out/figure.png"]), function (r) {
        var files = (r.written || []).filter(function (f) {
          return /out\/figure-steps\/step_\d+\.png$/.test(f[0]);
        }).sort(function (a, b) { return a[0] < b[0] ? -1 : 1; });
        steps = files.map(function (f) {
          return URL.createObjectURL(new Blob([f[1]], {type: "image/png"}));
        });
        if (!steps.length) {
          start.textContent = "could not draw it here" + (r.error ? ": " + r.error : "");
          return;
        }
        img = document.createElement("img");
        img.className = "figure-picture";
        img.alt = "the picture after the faces drawn so far; click a pixel to trace it";
        img.addEventListener("click", traceAt);
        body.insertBefore(img, trace);
        slider.max = String(steps.length - 1);
        slider.value = String(steps.length - 1);
        showStep();
        start.hidden = true;
        body.hidden = false;
        fig.setAttribute("data-state", "ready");
      });
    });
    slider.addEventListener("input", showStep);
    function traceAt(e) {
      var x = Math.floor(e.offsetX * FIGURE_W / img.clientWidth);
      var y = Math.floor(e.offsetY * FIGURE_H / img.clientHeight);
      trace.textContent = "tracing pixel (" + x + "," + y + ")...";
      ask(lesson, size.concat(["--trace", x + "," + y, "--out", "out/figure-trace.png"]), function (r) {
        var text = r.printed || r.error || "", at = text.search(/^(trace pixel|no fragment)/m);
        trace.textContent = at >= 0 ? text.slice(at) : text;
        fig.setAttribute("data-state", "traced");
      });
    }
  });

  /* A flags figure: a select per --flag=a|b|c of its arguments (the first
   * chosen at first), the rest as they are; show=--flag names the picture to
   * show, else --out's. Each choice runs the lesson again. It keeps the
   * arguments of its last run in data-run and counts its runs in data-runs. */
  function flagsFigure(fig) {
    var lesson = fig.getAttribute("data-lesson"), fixed = [], choices = [], show = null;
    (fig.getAttribute("data-args") || "").split(/\s+/).filter(Boolean).forEach(function (a) {
      var m = /^(--[\w-]+)=(.+\|.+)$/.exec(a), s = /^show=(--[\w-]+)$/.exec(a);
      if (m) choices.push({flag: m[1], values: m[2].split("|")});
      else if (s) show = s[1];
      else fixed.push(a);
    });
    var box = fig.querySelector(".figure-choices"), body = fig.querySelector(".figure-body");
    var start = fig.querySelector(".figure-start"), pre = fig.querySelector(".figure-trace");
    fig.querySelector(".figure-slider").remove();
    fig.querySelector(".figure-step").remove();
    var img = null, runs = 0;
    choices.forEach(function (c) {
      var label = document.createElement("label"), sel = document.createElement("select");
      label.textContent = c.flag + " ";
      c.values.forEach(function (v) {
        var o = document.createElement("option");
        o.value = o.textContent = v;
        sel.appendChild(o);
      });
      sel.addEventListener("change", function () { if (img) draw(); });
      c.select = sel;
      label.appendChild(sel);
      box.appendChild(label);
    });
    function draw() {
      var args = fixed.slice();
      choices.forEach(function (c) { args.push(c.flag, c.select.value); });
      args.push("--width", "400", "--height", "300", "--out", "out/figure-flags.png");
      if (show) args.push(show, "out/figure-flags-shown.png");
      pre.textContent = "running " + lesson + " in the page...";
      ask(lesson, args, function (r) {
        var want = show ? "out/figure-flags-shown.png" : "out/figure-flags.png";
        var f = (r.written || []).filter(function (w) { return w[0] === want; })[0];
        if (!img) {
          img = document.createElement("img");
          img.className = "figure-picture";
          body.insertBefore(img, pre);
        }
        img.alt = "what " + lesson + " " + args.join(" ") + " drew";
        if (f) img.src = URL.createObjectURL(new Blob([f[1]], {type: "image/png"}));
        else img.removeAttribute("src"); /* no picture this run: not the last one's */
        pre.textContent = r.printed || r.error || "";
        fig.setAttribute("data-run", args.join(" "));
        fig.setAttribute("data-runs", String(++runs));
        fig.setAttribute("data-state", "ready");
      });
    }
    start.addEventListener("click", function () {
      start.hidden = true;
      body.hidden = false;
      draw();
    });
  }

  Array.prototype.forEach.call(document.querySelectorAll(".run"), function (widget) {
    widget.querySelector(".run-button").addEventListener("click", function () { run(widget); });
    widget.querySelector(".run-cmd").addEventListener("keydown", function (e) {
      if (e.key === "Enter") run(widget);
    });
  });
})();
