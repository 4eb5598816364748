// The site's motion player: every <div class="wb-motion" data-chapter="ID"> becomes
// a player of that chapter's scenes: the bodies moving in the same view as the strobe
// pictures and animations, play / pause, a scrub bar, a speed choice, and below them the
// chapter's own energy and momentum figure of the scene with a cursor that moves in step.
// Plain JavaScript and SVG; the scenes' data come from <scene>.player.js files and the
// figures' panel positions from <scene>.panels.json, bundled into <script> files by
// plots/site_motion.py, so nothing is fetched and the page works offline from a folder.
(function () {
  "use strict";
  var NS = "http://www.w3.org/2000/svg";
  var SPEEDS = [0.1, 0.25, 0.5, 1, 2];
  var TICK_MS = 40;

  function el(tag, attrs, parent, text) {
    var node = document.createElementNS(NS, tag);
    for (var k in attrs) node.setAttribute(k, attrs[k]);
    if (text !== undefined) node.textContent = text;
    if (parent) parent.appendChild(node);
    return node;
  }
  function html(tag, attrs, parent, text) {
    var node = document.createElement(tag);
    for (var k in attrs) node.setAttribute(k, attrs[k]);
    if (text !== undefined) node.textContent = text;
    if (parent) parent.appendChild(node);
    return node;
  }
  function nearest(times, t) {
    var lo = 0, hi = times.length - 1;
    while (lo < hi) { var mid = (lo + hi) >> 1; if (times[mid] < t) lo = mid + 1; else hi = mid; }
    if (lo > 0 && Math.abs(times[lo - 1] - t) <= Math.abs(times[lo] - t)) lo -= 1;
    return lo;
  }
  function niceStep(span, count) {
    var raw = span / count, power = Math.pow(10, Math.floor(Math.log10(raw)));
    var steps = [1, 2, 2.5, 5, 10];
    for (var i = 0; i < steps.length; i++) if (steps[i] * power >= raw * 0.999) return steps[i] * power;
    return 10 * power;
  }
  function label(v) { var s = Math.abs(v) < 1e-12 ? "0" : String(+v.toPrecision(4)); return s.replace("-", "\u2212"); }

  var STYLE = ".wb-motion{border:1px solid #ccc;border-radius:6px;padding:10px;margin:1em 0;background:#fff;color:#202020;font-family:'DejaVu Sans',sans-serif}" +
    ".wb-motion svg{display:block;width:100%;height:auto;background:#fff}" +
    ".wb-motion .wb-bar{display:flex;flex-wrap:wrap;align-items:center;gap:10px;margin:6px 0}" +
    ".wb-motion .wb-bar input[type=range]{flex:1;min-width:200px}" +
    ".wb-motion .wb-figure{position:relative;margin-top:6px}.wb-motion .wb-figure img{display:block;width:100%;height:auto}" +
    ".wb-motion .wb-figure svg{position:absolute;left:0;top:0;width:100%;height:100%;background:none;pointer-events:none}" +
    ".wb-motion button{min-width:5.5em}.wb-motion .wb-time{font-variant-numeric:tabular-nums;min-width:8em}";

  function Player(root, scenes) {
    this.root = root; this.scenes = scenes; this.playing = false; this.t = 0; this.speed = 1;
    root.innerHTML = "";
    var bar = html("div", {"class": "wb-bar"}, root);
    html("label", {}, bar, "Scene ");
    this.select = html("select", {"class": "wb-scene", "aria-label": "scene"}, bar);
    var self = this;
    scenes.forEach(function (s, i) { html("option", {value: i}, self.select, s.title); });
    this.select.addEventListener("change", function () { self.load(+self.select.value); });
    this.stageBox = html("div", {}, root);
    var controls = html("div", {"class": "wb-bar"}, root);
    this.button = html("button", {"class": "wb-play", type: "button"}, controls, "\u25B6 play");
    this.button.addEventListener("click", function () { self.toggle(); });
    this.scrub = html("input", {"class": "wb-scrub", type: "range", min: 0, max: 1000, value: 0, step: 1, "aria-label": "time"}, controls);
    this.scrub.addEventListener("input", function () { self.pause(); self.show(self.scrub.value / 1000 * self.scene.duration); });
    this.timeText = html("span", {"class": "wb-time"}, controls);
    html("label", {}, controls, "speed ");
    this.speedSelect = html("select", {"class": "wb-speed", "aria-label": "speed"}, controls);
    SPEEDS.forEach(function (v) { var o = html("option", {value: v}, self.speedSelect, v + "\u00D7"); if (v === 1) o.selected = true; });
    this.speedSelect.addEventListener("change", function () { self.speed = +self.speedSelect.value; self.showSpeed(); });
    this.speedText = html("span", {"class": "wb-speed-text"}, controls);
    this.charts = html("div", {"class": "wb-charts"}, root);
    this.load(0);
    setInterval(function () { self.tick(); }, TICK_MS);
  }

  Player.prototype.load = function (index) {
    this.pause();
    var s = this.scene = this.scenes[index];
    var W = 960, H = 540, b = s.box;
    var sx = function (x) { return (x - b[0]) / (b[1] - b[0]) * W; };
    var sy = function (y) { return H - (y - b[2]) / (b[3] - b[2]) * H; };
    this.sx = sx; this.sy = sy;
    this.stageBox.innerHTML = "";
    var svg = el("svg", {viewBox: "0 0 " + W + " " + (H + 40), "class": "wb-stage", role: "img",
                         "aria-label": s.title + ", " + s.view.name}, this.stageBox);
    // Grid every round metre step, labelled on the edges.
    var step = niceStep(b[1] - b[0], 8), g = el("g", {stroke: "#E4E4E4", "stroke-width": 1}, svg);
    for (var x = Math.ceil(b[0] / step) * step; x <= b[1]; x += step) {
      el("line", {x1: sx(x), x2: sx(x), y1: 0, y2: H}, g);
      el("text", {x: sx(x), y: H + 18, "text-anchor": "middle", "font-size": 14, fill: "#404040", stroke: "none"}, svg, label(x));
    }
    for (var y = Math.ceil(b[2] / step) * step; y <= b[3]; y += step) {
      el("line", {x1: 0, x2: W, y1: sy(y), y2: sy(y)}, g);
      if (sy(y) > 48) el("text", {x: 4, y: sy(y) - 3, "font-size": 14, fill: "#404040"}, svg, label(y));  // the clock's corner
    }
    el("text", {x: W / 2, y: H + 36, "text-anchor": "middle", "font-size": 15}, svg, s.view.x + "   (" + s.view.name + "; vertical: " + s.view.y + ")");
    s.planes.forEach(function (p) {
      el("polygon", {points: p.band.map(function (q) { return sx(q[0]) + "," + sy(q[1]); }).join(" "), fill: "#E4E4E4"}, svg);
      el("line", {x1: sx(p.line[0][0]), y1: sy(p.line[0][1]), x2: sx(p.line[1][0]), y2: sy(p.line[1][1]), stroke: "#505050", "stroke-width": 3}, svg);
    });
    this.shapes = s.runs.map(function (run) {
      return s.bodies.map(function (body) {
        var colour = run.student ? "#CC79A7" : body.colour;
        var attrs = {stroke: colour, "stroke-width": run.student ? 3.5 : 2.5, fill: run.student ? "none" : colour,
                     "fill-opacity": 0.25};
        if (run.student) attrs["stroke-dasharray"] = "10 6";
        // A box's own axes, centre to face middles (plots/motion.py, box_hands).
        var hands = [0, 1, 2].map(function () {
          var line = el("line", {stroke: colour, "stroke-width": run.student ? 2.5 : 2}, svg);
          if (run.student) line.setAttribute("stroke-dasharray", "6 4");
          return line;
        });
        // A dot at the centre, so that even a 5 mm bullet shows (as in the strobe pictures).
        var dot = el("circle", {r: 3.5, fill: colour}, svg);
        return {circle: el("circle", attrs, svg), polygon: el("polygon", attrs, svg), hands: hands, dot: dot};
      });
    });
    // Each touch: an arrow along its normal at the contact point, and a line of text listed
    // under the clock while it shows (several touches at once would cover one another).
    this.touches = s.runs.map(function (run) {
      return run.touches.map(function (c) {
        var colour = run.student ? "#CC79A7" : "#B2182B", group = el("g", {visibility: "hidden"}, svg);
        var x1 = sx(c.from[0]), y1 = sy(c.from[1]), x2 = sx(c.to[0]), y2 = sy(c.to[1]);
        var a = Math.atan2(y2 - y1, x2 - x1), h = 14;
        // The student's arrow is dashed with an open head, narrower: over the reference's at the
        // same touch it leaves that one in sight.
        var shaft = {x1: x1, y1: y1, x2: x2, y2: y2, stroke: colour, "stroke-width": run.student ? 2.5 : 4};
        if (run.student) shaft["stroke-dasharray"] = "6 4";
        el("line", shaft, group);
        el("polygon", {points: [x2 + h * Math.cos(a), y2 + h * Math.sin(a), x2 + h * Math.cos(a + 2.4), y2 + h * Math.sin(a + 2.4),
                                x2 + h * Math.cos(a - 2.4), y2 + h * Math.sin(a - 2.4)].join(" "),
                       fill: run.student ? "none" : colour, stroke: run.student ? colour : "none", "stroke-width": 2.5}, group);
        var text = el("text", {x: 12, y: 0, "font-size": 20, fill: colour, "paint-order": "stroke", stroke: "#fff",
                               "stroke-width": 5, visibility: "hidden", "class": "wb-touch"}, svg,
                      (run.student ? "your code: " : "") + c.text + " at t = " + label(c.t) + " s");
        return {t: c.t, node: group, text: text};
      });
    });
    this.clock = el("text", {x: 12, y: 28, "font-size": 22, "paint-order": "stroke", stroke: "#fff", "stroke-width": 5}, svg);
    // The key: each body's name in its colour (a crowd shares colours: plots/motion.py, key_entries).
    var key = el("text", {x: W - 12, y: 28, "text-anchor": "end", "font-size": 18, "paint-order": "stroke", stroke: "#fff",
                          "stroke-width": 5, "class": "wb-key"}, svg);
    var entries = s.key.slice();
    if (s.runs.some(function (run) { return run.student; })) entries.push(["your code (dashed)", "#CC79A7"]);
    entries.forEach(function (e, n) { el("tspan", {fill: e[1], dx: n ? 14 : 0}, key, "\u25A0 " + e[0]); });
    this.cursors = this.figure();
    this.showSpeed();
    this.show(0);
  };

  // The scene's energy and momentum: the chapter's own figure (the SVG the page shows), with
  // a cursor on each of its panels. Where each panel's plot area lies and the range of its
  // time axis come from the figure's .panels.json, written by plots/figures.py from gnuplot's
  // own numbers, so the cursor stands exactly at the time shown.
  Player.prototype.figure = function () {
    var s = this.scene, figure = (window.WorkbookMotionFigures || {})[s.chapter + "/" + s.scene];
    this.charts.innerHTML = "";
    if (!figure) {
      html("p", {"class": "wb-no-figure"}, this.charts, "(No energy and momentum figure for this scene: run ./workbook figures.)");
      return [];
    }
    var box = html("div", {"class": "wb-figure"}, this.charts);
    html("img", {src: figure.src, alt: "Energy and momentum over time: " + s.title}, box);
    var svg = el("svg", {viewBox: "0 0 " + figure.width + " " + figure.height, preserveAspectRatio: "none",
                         "aria-hidden": "true"}, box);
    return figure.panels.map(function (p) {
      var x = function (t) {
        var u = (t * figure.x_per_second - p.x0) / (p.x1 - p.x0);
        return p.left + Math.max(0, Math.min(1, u)) * (p.right - p.left);
      };
      var node = el("line", {"class": "wb-cursor", x1: x(0), x2: x(0), y1: p.top, y2: p.bottom, stroke: "#B2182B",
                             "stroke-width": 2.5, "stroke-opacity": 0.85}, svg);
      return {node: node, x: x};
    });
  };

  Player.prototype.showSpeed = function () {
    var f = this.scene.slow_motion * 1 / this.speed, text;
    text = Math.abs(f - 1) < 1e-9 ? "real time" : f > 1 ? "slow motion \u00D7" + label(f) : "fast motion \u00D7" + label(1 / f);
    this.speedText.textContent = "(" + text + (this.speed === 1 ? ", as the video" : "") + ")";
  };

  Player.prototype.show = function (t) {
    var s = this.scene, self = this;
    this.t = Math.max(0, Math.min(t, s.duration));
    s.runs.forEach(function (run, r) {
      var k = nearest(run.t, self.t);
      run.shapes[k].forEach(function (shape, i) {
        var nodes = self.shapes[r][i];
        if (shape.c) {
          nodes.circle.setAttribute("cx", self.sx(shape.c[0])); nodes.circle.setAttribute("cy", self.sy(shape.c[1]));
          nodes.circle.setAttribute("r", shape.c[2] / (s.box[1] - s.box[0]) * 960);
        } else {
          nodes.polygon.setAttribute("points", shape.p.map(function (q) { return self.sx(q[0]) + "," + self.sy(q[1]); }).join(" "));
        }
        var centre = shape.c || (shape.a ? shape.a[0] : null);
        nodes.dot.setAttribute("visibility", centre ? "visible" : "hidden");
        if (centre) { nodes.dot.setAttribute("cx", self.sx(centre[0])); nodes.dot.setAttribute("cy", self.sy(centre[1])); }
        nodes.hands.forEach(function (line, n) {
          var a = shape.a ? shape.a[n] : null;
          line.setAttribute("visibility", a ? "visible" : "hidden");
          if (a) {
            line.setAttribute("x1", self.sx(a[0])); line.setAttribute("y1", self.sy(a[1]));
            line.setAttribute("x2", self.sx(a[2])); line.setAttribute("y2", self.sy(a[3]));
          }
        });
      });
    });
    // A touch shows while it happens and for a moment after, as in the films (plots/motion.py).
    var listed = 0;
    this.touches.forEach(function (touches) {
      touches.forEach(function (c) {
        var on = c.t <= self.t + 1e-12 && self.t <= c.t + s.touch_window;
        c.node.setAttribute("visibility", on ? "visible" : "hidden");
        c.text.setAttribute("visibility", on ? "visible" : "hidden");
        if (on) c.text.setAttribute("y", 56 + 24 * listed++);
      });
    });
    this.cursors.forEach(function (c) { c.node.setAttribute("x1", c.x(self.t)); c.node.setAttribute("x2", c.x(self.t)); });
    this.clock.textContent = "t = " + this.t.toFixed(4) + " s";
    this.timeText.textContent = "t = " + this.t.toFixed(4) + " s";
    this.scrub.value = Math.round(this.t / s.duration * 1000);
    this.root.setAttribute("data-time", this.t.toFixed(6));
  };

  Player.prototype.play = function () {
    if (this.t >= this.scene.duration) this.show(0);
    this.playing = true; this.last = Date.now(); this.button.textContent = "\u275A\u275A pause";
    this.root.setAttribute("data-playing", "true");
  };
  Player.prototype.pause = function () {
    this.playing = false; if (this.button) this.button.textContent = "\u25B6 play";
    this.root.setAttribute("data-playing", "false");
  };
  Player.prototype.toggle = function () { if (this.playing) this.pause(); else this.play(); };
  // `now` (ms) defaults to the clock; the site's test passes its own to check the speed exactly.
  Player.prototype.tick = function (now) {
    if (!this.playing) return;
    if (now === undefined) now = Date.now();
    var dt = (now - this.last) / 1000; this.last = now;
    this.show(this.t + dt * this.speed / this.scene.slow_motion);
    if (this.t >= this.scene.duration) this.pause();
  };

  function start() {
    var style = document.createElement("style"); style.textContent = STYLE; document.head.appendChild(style);
    var all = window.WorkbookMotion || [];
    Array.prototype.forEach.call(document.querySelectorAll(".wb-motion"), function (root) {
      var chapter = root.getAttribute("data-chapter");
      var scenes = all.filter(function (s) { return s.chapter === chapter; });
      if (!scenes.length) { root.textContent = "No motion data for chapter " + chapter + " (run ./workbook figures)."; return; }
      var player = new Player(root, scenes);
      root.wbPlayer = player;
      if (/autoplay/.test(window.location.hash)) player.play();
    });
  }
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start); else start();
})();
