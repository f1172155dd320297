// curvbench results site: charts from the page's embedded JSON (Chart.js), sortable tables and
// the leaderboard, whose view (quantity, norm, filters, sort) lives in the URL's hash.
(function () {
  "use strict";
  var data = JSON.parse(document.getElementById("site-data").textContent);

  function fmtSci(x) {
    if (x === null || !isFinite(x)) return "n/a";
    return x.toExponential(2);
  }
  function fmt2(x) {
    if (x === null || !isFinite(x)) return "n/a";
    return x.toFixed(2);
  }

  // ---- charts ---------------------------------------------------------------------------
  var markerStyles = ["circle", "rect", "triangle", "rectRot", "star", "crossRot", "cross"];
  var charts = [];
  window.curvbenchCharts = charts;
  function drawCharts() {
    if (!data.plots || typeof Chart === "undefined") return;
    var canvases = document.querySelectorAll("canvas[data-plot]");
    for (var i = 0; i < canvases.length; i++) {
      var canvas = canvases[i];
      var plot = data.plots[canvas.getAttribute("data-plot")];
      if (!plot) continue;
      var datasets = plot.series.map(function (s, k) {
        var colour = s.color || "#444444";
        return {
          label: s.label,
          data: s.data.map(function (p) { return { x: p[0], y: p[1], note: p[2] }; }),
          borderColor: colour,
          backgroundColor: colour,
          showLine: !s.points_only,
          borderDash: s.dash > 1 ? [6, 4] : [],
          borderWidth: s.marker === 0 ? 1 : 2,
          pointRadius: s.marker === 0 ? 0 : 3.5,
          pointStyle: markerStyles[Math.abs(s.marker || 0) % markerStyles.length],
          order: k
        };
      });
      var chart = new Chart(canvas.getContext("2d"), {
        type: "scatter",
        data: { datasets: datasets },
        options: {
          animation: false,
          responsive: true,
          maintainAspectRatio: false,
          plugins: {
            title: { display: true, text: plot.title.replace("\\n", " ") },
            legend: { position: "right" },
            tooltip: {
              callbacks: {
                label: function (ctx) {
                  var p = ctx.raw;
                  return ctx.dataset.label + ": " + fmtSci(p.y) + " at " + plot.x + " " +
                    fmtSci(p.x) + (p.note ? " (" + p.note + ")" : "");
                }
              }
            }
          },
          scales: {
            x: { type: plot.logx ? "logarithmic" : "linear", reverse: plot.reverse,
                 title: { display: true, text: plot.x } },
            y: { type: plot.logy ? "logarithmic" : "linear",
                 title: { display: true, text: plot.y } }
          }
        }
      });
      charts.push({ id: canvas.getAttribute("data-plot"), series: datasets.length, chart: chart });
      canvas.setAttribute("data-rendered", String(datasets.length));
    }
  }

  // ---- sortable tables ------------------------------------------------------------------
  function cellKey(td) {
    var v = td.getAttribute("data-value");
    return v === null ? null : parseFloat(v);
  }
  function sortRows(rows, keyOf, dir) {
    // Stable: ties keep their order; rows without a number go last either way.
    var indexed = rows.map(function (r, i) { return { r: r, i: i, k: keyOf(r) }; });
    indexed.sort(function (a, b) {
      var an = a.k === null || typeof a.k === "number" && !isFinite(a.k);
      var bn = b.k === null || typeof b.k === "number" && !isFinite(b.k);
      if (an !== bn) return an ? 1 : -1;
      if (!an && a.k !== b.k) {
        var c = a.k < b.k ? -1 : 1;
        return dir === "desc" ? -c : c;
      }
      return a.i - b.i;
    });
    return indexed.map(function (x) { return x.r; });
  }
  function makeSortable(table) {
    var heads = table.querySelectorAll("thead th");
    heads.forEach(function (th, col) {
      th.classList.add("sortable-head");
      th.addEventListener("click", function () {
        var dir = th.getAttribute("data-dir") === "asc" ? "desc" : "asc";
        heads.forEach(function (h) { h.removeAttribute("data-dir"); });
        th.setAttribute("data-dir", dir);
        var body = table.tBodies[0];
        var rows = Array.prototype.slice.call(body.rows);
        var numeric = rows.some(function (r) { return r.cells[col] && cellKey(r.cells[col]) !== null; });
        var sorted = sortRows(rows, function (r) {
          var td = r.cells[col];
          if (!td) return null;
          return numeric ? cellKey(td) : td.textContent.toLowerCase();
        }, dir);
        sorted.forEach(function (r) { body.appendChild(r); });
      });
    });
  }

  // ---- leaderboard ----------------------------------------------------------------------
  var QUANTITIES = ["normal", "H", "K", "k1", "k2", "d1"];
  var NORMS = ["L2", "Linf"];
  var METRICS = [
    { key: "error", title: "error", better: "low", fmt: fmtSci },
    { key: "rate", title: "rate", better: "high", fmt: fmt2 },
    { key: "us", title: "us/vertex", better: "low", fmt: fmt2 }
  ];
  function readHash() {
    var state = {};
    location.hash.replace(/^#/, "").split("&").forEach(function (kv) {
      if (!kv) return;
      var i = kv.indexOf("=");
      state[decodeURIComponent(kv.slice(0, i))] = decodeURIComponent(kv.slice(i + 1));
    });
    return state;
  }
  function writeHash(state) {
    var parts = Object.keys(state).filter(function (k) { return state[k] !== ""; })
      .map(function (k) { return encodeURIComponent(k) + "=" + encodeURIComponent(state[k]); });
    history.replaceState(null, "", "#" + parts.join("&"));
  }
  function leaderboard() {
    var table = document.getElementById("leaderboard");
    if (!table || !data.rows) return;
    var classes = data.classes;
    var groups = [];
    var methods = [];
    var cell = {};  // method|class|quantity|norm -> row
    data.rows.forEach(function (r) {
      if (groups.indexOf(r[1]) < 0) groups.push(r[1]);
      if (methods.indexOf(r[0]) < 0) methods.push(r[0]);
      cell[r[0] + "|" + r[2] + "|" + r[3] + "|" + r[4]] =
        { group: r[1], error: r[5], rate: r[6], us: r[7], experiment: r[8], meshes: r[9] };
    });
    var groupOf = {};
    data.rows.forEach(function (r) { groupOf[r[0]] = r[1]; });
    var defaults = { q: "H", norm: "L2", sort: "", dir: "asc", hide: "", classes: "", noise: "all" };
    var state = Object.assign({}, defaults, readHash());

    var controls = document.getElementById("leaderboard-controls");
    function select(name, label, options) {
      var wrap = document.createElement("label");
      wrap.textContent = label + " ";
      var sel = document.createElement("select");
      sel.id = "lb-" + name;
      options.forEach(function (o) {
        var opt = document.createElement("option");
        opt.value = o[0];
        opt.textContent = o[1];
        sel.appendChild(opt);
      });
      sel.value = state[name];
      sel.addEventListener("change", function () { state[name] = sel.value; render(); });
      wrap.appendChild(sel);
      controls.appendChild(wrap);
    }
    select("q", "quantity", QUANTITIES.map(function (q) { return [q, q]; }));
    select("norm", "norm", NORMS.map(function (n) { return [n, n]; }));
    select("noise", "noise", [["all", "all meshes"], ["none", "noise-free"], ["noisy", "noisy"]]);
    function checkboxes(name, title, items) {
      var box = document.createElement("fieldset");
      box.id = "lb-" + name;
      var legend = document.createElement("legend");
      legend.textContent = title;
      box.appendChild(legend);
      items.forEach(function (it) {
        var lab = document.createElement("label");
        var cb = document.createElement("input");
        cb.type = "checkbox";
        cb.value = it[0];
        cb.checked = state[name].split(",").indexOf(it[0]) < 0;
        cb.addEventListener("change", function () {
          var off = [];
          box.querySelectorAll("input").forEach(function (c) { if (!c.checked) off.push(c.value); });
          state[name] = off.join(",");
          render();
        });
        lab.appendChild(cb);
        lab.appendChild(document.createTextNode(" " + it[1]));
        box.appendChild(lab);
      });
      controls.appendChild(box);
    }
    checkboxes("hide", "estimator family", groups.map(function (g) { return [g, g]; }));
    checkboxes("classes", "mesh class", classes.map(function (c) { return [c.id, c.title]; }));

    function visibleClasses() {
      var off = state.classes.split(",");
      return classes.filter(function (c) {
        if (off.indexOf(c.id) >= 0) return false;
        var noisy = c.id.indexOf("noisy") === 0;
        if (state.noise === "none" && noisy) return false;
        if (state.noise === "noisy" && !noisy) return false;
        return true;
      });
    }
    function render() {
      var cls = visibleClasses();
      var hidden = state.hide.split(",");
      var rows = methods.filter(function (m) {
        if (hidden.indexOf(groupOf[m]) >= 0) return false;
        return cls.some(function (c) { return cell[m + "|" + c.id + "|" + state.q + "|" + state.norm]; });
      });
      function value(m, cid, key) {
        var c = cell[m + "|" + cid + "|" + state.q + "|" + state.norm];
        return c ? c[key] : null;
      }
      if (state.sort) {
        var parts = state.sort.split(":");
        rows = sortRows(rows, function (m) {
          if (parts[0] === "method") return m.toLowerCase();
          var v = value(m, parts[0], parts[1]);
          return v === null ? null : v;
        }, state.dir);
      }
      table.innerHTML = "";
      var thead = table.createTHead();
      var top = thead.insertRow();
      var th = document.createElement("th");
      th.rowSpan = 2;
      th.textContent = "estimator";
      th.setAttribute("data-sort", "method");
      top.appendChild(th);
      var tg = document.createElement("th");
      tg.rowSpan = 2;
      tg.textContent = "family";
      top.appendChild(tg);
      var sub = thead.insertRow();
      cls.forEach(function (c) {
        var h = document.createElement("th");
        h.colSpan = METRICS.length;
        h.textContent = c.title;
        top.appendChild(h);
        METRICS.forEach(function (mt) {
          var s = document.createElement("th");
          s.className = "num sortable-head";
          s.textContent = mt.title;
          s.setAttribute("data-sort", c.id + ":" + mt.key);
          s.title = "sort by " + c.title + " " + mt.title;
          sub.appendChild(s);
        });
      });
      thead.querySelectorAll("th[data-sort]").forEach(function (h) {
        h.classList.add("sortable-head");
        if (h.getAttribute("data-sort") === state.sort) h.setAttribute("data-dir", state.dir);
        h.addEventListener("click", function () {
          var key = h.getAttribute("data-sort");
          if (state.sort === key) state.dir = state.dir === "asc" ? "desc" : "asc";
          else {
            state.sort = key;
            var metric = key.split(":")[1];
            state.dir = metric === "rate" ? "desc" : "asc";
          }
          render();
        });
      });
      // Best per column.
      var best = {};
      cls.forEach(function (c) {
        METRICS.forEach(function (mt) {
          var b = null;
          rows.forEach(function (m) {
            var v = value(m, c.id, mt.key);
            if (v === null || !isFinite(v)) return;
            if (b === null || (mt.better === "low" ? v < b : v > b)) b = v;
          });
          best[c.id + ":" + mt.key] = b;
        });
      });
      var body = table.createTBody();
      rows.forEach(function (m) {
        var tr = body.insertRow();
        tr.setAttribute("data-method", m);
        var name = tr.insertCell();
        name.textContent = m;
        tr.insertCell().textContent = groupOf[m];
        cls.forEach(function (c) {
          var info = cell[m + "|" + c.id + "|" + state.q + "|" + state.norm];
          METRICS.forEach(function (mt) {
            var td = tr.insertCell();
            td.className = "num";
            var v = info ? info[mt.key] : null;
            if (v === null || v === undefined) { td.textContent = "-"; return; }
            td.setAttribute("data-value", String(v));
            if (mt.key === "error" && info.experiment) {
              var a = document.createElement("a");
              a.href = "exp-" + info.experiment + ".html";
              a.textContent = mt.fmt(v);
              a.title = info.meshes;
              td.appendChild(a);
            } else {
              td.textContent = mt.fmt(v);
            }
            if (v === best[c.id + ":" + mt.key]) td.classList.add("best");
          });
        });
      });
      writeHash(state);
    }
    // A link or the back button changing the hash: the view follows it.
    function syncControls() {
      ["q", "norm", "noise"].forEach(function (name) {
        document.getElementById("lb-" + name).value = state[name];
      });
      ["hide", "classes"].forEach(function (name) {
        var off = state[name].split(",");
        document.querySelectorAll("#lb-" + name + " input").forEach(function (c) {
          c.checked = off.indexOf(c.value) < 0;
        });
      });
    }
    window.addEventListener("hashchange", function () {
      state = Object.assign({}, defaults, readHash());
      syncControls();
      render();
    });
    render();
  }

  document.querySelectorAll("table.sortable").forEach(makeSortable);
  leaderboard();
  drawCharts();
})();
