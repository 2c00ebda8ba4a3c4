// The casteljau explorer: views that send every geometry to the server (POST /api/COMMAND,
// the command line's requests and responses) and draw the answers in SVG. Plain modern
// JavaScript, no library. Each view keeps its state (points, t, knots...) and redraws
// from the server's answers; a drag sends at most one batch of requests at a time and,
// when it ends, one more with the latest state (requests coalesced, never queued).
"use strict";

const SVG_NS = "http://www.w3.org/2000/svg";

// ---------------------------------------------------------------------------------------
// Helpers.

function el(tag, attrs, parent) {
  if (parent && parent.reuse) return reused(parent, tag, attrs || {});
  const e = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

// A figure drawn again from scratch without rebuilding its elements: after redraw(svg),
// el(tag, attrs, svg) hands back the element the last drawing made for the same tag,
// class and id in the same order (its attributes updated, those no longer given removed; a
// group emptied), and the drawing's end (a microtask: drawings are synchronous) puts the
// elements in the order drawn and removes the ones not drawn again. During a drag the
// browser then restyles and lays out a few changed attributes instead of a hundred new
// elements.
function redraw(svg) {
  if (svg.reuse) return;
  svg.reuse = { used: new Map(), order: [] };
  if (!svg.pool) svg.pool = new Map();
  queueMicrotask(() => {
    const r = svg.reuse;
    svg.reuse = null;
    let next = svg.firstChild;
    for (const e of r.order) {
      if (e === next) next = next.nextSibling;
      else svg.insertBefore(e, next);
    }
    while (next) {
      const after = next.nextSibling;
      next.remove();
      next = after;
    }
    for (const [key, list] of svg.pool) list.length = r.used.get(key) || 0;
  });
}

function reused(svg, tag, attrs) {
  const r = svg.reuse;
  const key = tag + "." + (attrs.class || "") + "#" + (attrs.id || "");
  const n = r.used.get(key) || 0;
  r.used.set(key, n + 1);
  let list = svg.pool.get(key);
  if (!list) svg.pool.set(key, (list = []));
  let e = list[n];
  if (!e) {
    e = document.createElementNS(SVG_NS, tag);
    e.given = {};
    list.push(e);
  } else if (tag === "g") {
    e.replaceChildren();
  }
  for (const k of Object.keys(e.given)) if (!(k in attrs)) e.removeAttribute(k);
  const given = {};
  for (const [k, v] of Object.entries(attrs)) {
    const text = String(v);
    if (e.given[k] !== text) e.setAttribute(k, text);
    given[k] = text;
  }
  e.given = given;
  r.order.push(e);
  return e;
}

function fmt(x) {
  return typeof x === "number" ? x.toFixed(4) : String(x);
}

function fmtPoint(p) {
  return "(" + p.map(fmt).join(", ") + ")";
}

function linspace(a, b, n) {
  const out = [];
  for (let i = 0; i < n; i++) out.push(a + ((b - a) * i) / (n - 1));
  return out;
}

const status = document.getElementById("status");
let pendingRequests = 0;

const idleWaiters = [];

function setPending(delta) {
  pendingRequests += delta;
  document.body.dataset.pending = String(pendingRequests);
  if (pendingRequests === 0) {
    // After the drawing that follows the last answer.
    setTimeout(() => {
      if (pendingRequests === 0) for (const resolve of idleWaiters.splice(0)) resolve();
    }, 0);
  }
}

// Resolves when no request is in flight and the answers are drawn (for tests and scripts).
window.explorerIdle = () => new Promise((resolve) => (pendingRequests === 0 ? resolve() : idleWaiters.push(resolve)));

// One command on the server: the response object, or an Error with the server's message.
// The commands asked in one turn of the event loop (a view's update asks for all it needs
// at once) travel together, as one batch (POST /batch, one line per request, one answer
// line each): one round trip per update rather than one per command (in Chromium each
// request costs several milliseconds of its own, far more than the server's computing).
let batch = null;

function api(command, request) {
  return new Promise((resolve, reject) => {
    if (!batch) {
      batch = [];
      queueMicrotask(sendBatch);
    }
    batch.push({ command, request, resolve, reject });
  });
}

// A request whose answer does not change while a control point is dragged (the basis
// functions over the same parameters): the server's answer kept, by the request's text,
// for the next updates (the last 32). A failed request is not kept.
const kept = new Map();

function apiKept(command, request) {
  const key = command + " " + JSON.stringify(request);
  let answer = kept.get(key);
  if (!answer) {
    answer = api(command, request);
    answer.catch(() => kept.delete(key));
    kept.set(key, answer);
    if (kept.size > 32) kept.delete(kept.keys().next().value);
  }
  return answer;
}

// The round trip of each batch in milliseconds, from the request to its whole answer (the
// last 1000): the part of an update's latency spent outside the page's own drawing.
const roundTrips = [];
window.explorerRoundTrips = () => roundTrips.slice();

// Batches are answered to the page in the order they were sent (several may be in flight:
// see coalesced(), and a click's request beside a drag's), so that an older answer is
// never drawn over a newer one.
let delivered = Promise.resolve();

async function sendBatch() {
  const items = batch;
  batch = null;
  setPending(1);
  // The batch's times (performance.now()), read by coalesced(): sent, answered (the whole
  // body received), parsed; bytes, the answer's length.
  const timing = (items.timing = {});
  const transport = (async () => {
    const body = items.map((i) => JSON.stringify({ command: i.command, request: i.request })).join("\n") + "\n";
    timing.sent = performance.now();
    const res = await fetch("batch", { method: "POST", headers: { "Content-Type": "application/x-ndjson" }, body });
    const text = await res.text();
    timing.answered = performance.now();
    timing.bytes = text.length;
    roundTrips.push(timing.answered - timing.sent);
    if (roundTrips.length > 1000) roundTrips.shift();
    return { res, text };
  })();
  const previous = delivered;
  delivered = (async () => {
    try {
      const { res, text } = await transport;
      await previous;
      if (!res.ok) {
        let message = String(res.status);
        try {
          message = JSON.parse(text).error;
        } catch (_) {}
        for (const i of items) i.reject(new Error(i.command + ": " + message));
        return;
      }
      const lines = text.split("\n");
      const answers = lines.slice(0, items.length).map((line) => JSON.parse(line));
      timing.parsed = performance.now();
      items.forEach((item, k) => {
        const answer = answers[k];
        if (answer && typeof answer.error === "string" && Object.keys(answer).length === 1) item.reject(new Error(item.command + ": " + answer.error));
        else item.resolve(answer);
      });
    } catch (e) {
      for (const i of items) i.reject(e);
    } finally {
      setPending(-1);
    }
  })();
}

// The time from an input (a drag's move, a slider) to the drawing of the server's answer
// for it, in milliseconds, per update (the last 1000): for tests and for the curious.
const updateLatencies = [];
window.explorerLatencies = () => updateLatencies.slice();

// Where each update's time went (the last 1000), in milliseconds: wait (from the input to
// the start of its work: two updates already in flight), build (the requests written),
// server (its first batch's round trip: the browser's network stack, HTTP, the server's
// computing), parse (JSON, after the batch before it was drawn), draw (the page's SVG
// elements, and any later requests of the update), frame (the next frame's style, layout
// and paint: from its animation callbacks to the task after it; not part of the
// latency); bytes, the answer's size.
const updatePhases = [];
window.explorerPhases = () => updatePhases.slice();

function recordPhases(input, start, end, timing) {
  const b = timing && timing.parsed ? timing : null;
  const phase = {
    wait: start - input,
    build: b ? b.sent - start : 0,
    server: b ? b.answered - b.sent : 0,
    parse: b ? b.parsed - b.answered : 0,
    draw: b ? end - b.parsed : end - start,
    frame: 0,
    bytes: b ? b.bytes : 0,
  };
  updatePhases.push(phase);
  if (updatePhases.length > 1000) updatePhases.shift();
  requestAnimationFrame(() => {
    const f = performance.now();
    setTimeout(() => (phase.frame = performance.now() - f), 0);
  });
}

// Runs `work` (an async function that asks the server and draws) for the newest state:
// at once while fewer than `depth` runs are in flight, else once more when one ends, for
// the state then (inputs in between are merged: requests never queue behind each other,
// and the last state is always drawn). Answers are drawn in the order they were asked
// (sendBatch). One run at a time is the default: two in flight (the server computing
// them in its two workers) redrew no more often in a drag of a move per frame at degree
// 10 on the loaded 2-core machine (4 alternating runs of 120 frames at load 12: a median
// of 72 redraws with one, 76 with two), since the browser's network stack and the
// machine, not the server, set the round trip.
function coalesced(work, depth = 1) {
  let inFlight = 0;
  let again = false;
  let since = null;  // when the oldest input not yet sent arrived
  const start = () => {
    inFlight++;
    setPending(1);
    again = false;
    const t0 = since;
    since = null;
    const begun = performance.now();
    const running = work();
    const items = batch;  // the batch this run's first requests joined (sent at the next microtask)
    running.then(
      () => {
        status.textContent = "";
        const end = performance.now();
        recordPhases(t0, begun, end, items && items.timing);
        updateLatencies.push(end - t0);
        if (updateLatencies.length > 1000) updateLatencies.shift();
      },
      (e) => {
        status.textContent = e.message;
      },
    ).finally(() => {
      inFlight--;
      if (again) start();
      setPending(-1);
    });
  };
  return () => {
    if (since === null) since = performance.now();
    if (inFlight >= depth) {
      again = true;
      return;
    }
    start();
  };
}

// A figure: world coordinates (y up) mapped to the SVG's viewBox, with one scale for both
// axes (equal) or one per axis (a plot).
class Frame {
  // flip: y down, as in SVG documents.
  constructor(svg, xmin, xmax, ymin, ymax, margin = 20, equal = true, flip = false) {
    this.svg = svg;
    const vb = svg.viewBox.baseVal;
    this.w = vb.width;
    this.h = vb.height;
    this.equal = equal;
    this.flip = flip;
    this.set(xmin, xmax, ymin, ymax, margin);
  }
  set(xmin, xmax, ymin, ymax, margin = 20) {
    let sx = (this.w - 2 * margin) / (xmax - xmin), sy = (this.h - 2 * margin) / (ymax - ymin);
    if (this.equal) sx = sy = Math.min(sx, sy);
    this.sx = sx;
    this.sy = this.flip ? -sy : sy;
    this.ox = (this.w - sx * (xmax - xmin)) / 2 - sx * xmin;
    this.oy = this.flip ? (this.h - sy * (ymax - ymin)) / 2 - sy * ymin : (this.h + sy * (ymax - ymin)) / 2 + sy * ymin;
  }
  x(p) {
    return this.ox + this.sx * p[0];
  }
  y(p) {
    return this.oy - this.sy * p[1];
  }
  path(points) {
    return points.map((p, i) => (i ? "L" : "M") + this.x(p).toFixed(2) + " " + this.y(p).toFixed(2)).join("");
  }
  // The world point under a pointer event; screen, the inverse of the figure's screen
  // matrix when the caller keeps it (a drag takes it once: asking for it after a redraw
  // makes the browser lay the figure out there and then, 5.6 ms per move measured at
  // degree 10 under load, on top of the frame's own layout).
  world(ev, screen) {
    const m = screen || this.svg.getScreenCTM().inverse();
    const pt = new DOMPoint(ev.clientX, ev.clientY).matrixTransform(m);
    return [(pt.x - this.ox) / this.sx, (this.oy - pt.y) / this.sy];
  }
}

// Draggable circles: onMove(index, worldPoint) while dragging (mouse, pen or touch). The
// pointer is captured by the figure's SVG element, which outlives the redraws that
// replace the circle during the drag.
function dragHandle(frame, circle, index, onMove) {
  // A reused circle keeps its one listener; the newest drawing's frame, index and action.
  circle.drag = { frame, index, onMove };
  if (circle.dragBound) return;
  circle.dragBound = true;
  circle.addEventListener("pointerdown", (ev) => {
    ev.preventDefault();
    const svg = circle.drag.frame.svg, id = ev.pointerId;
    svg.setPointerCapture(id);
    const screen = svg.getScreenCTM().inverse();  // the figure does not move during a drag
    const move = (e) => {
      if (e.pointerId === id) circle.drag.onMove(circle.drag.index, circle.drag.frame.world(e, screen));
    };
    const up = (e) => {
      if (e.pointerId !== id) return;
      svg.removeEventListener("pointermove", move);
      svg.removeEventListener("pointerup", up);
      svg.removeEventListener("pointercancel", up);
    };
    svg.addEventListener("pointermove", move);
    svg.addEventListener("pointerup", up);
    svg.addEventListener("pointercancel", up);
  });
}

// A view's draggable handles (radius r) at its points: a drag moves the point and redraws.
function pointHandles(view, frame, svg, r) {
  view.points.forEach((p, i) => {
    const h = el("circle", { class: "handle", cx: frame.x(p), cy: frame.y(p), r, "data-index": i, "data-point": JSON.stringify(p) }, svg);
    dragHandle(frame, h, i, (index, w) => {
      view.points[index] = w;
      view.update();
    });
  });
}

// The convex hull of the control points (Andrew's monotone chain): a drawing aid for the
// convex hull property, not a geometry of the curve.
function convexHull(points) {
  const p = points.map((q) => q.slice()).sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  if (p.length < 3) return p;
  const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const lower = [];
  for (const q of p) {
    while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], q) <= 0) lower.pop();
    lower.push(q);
  }
  const upper = [];
  for (const q of p.slice().reverse()) {
    while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], q) <= 0) upper.pop();
    upper.push(q);
  }
  return lower.slice(0, -1).concat(upper.slice(0, -1));
}

const PALETTE = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"];

// A plot of basis functions: values[j][i] = function i at ts[j]; then extra(frame) draws
// more (the knots). Drawn again only when the values (a kept answer) or the cursor change.
function drawBasis(svg, ts, values, cursor, extra) {
  if (svg.drawn && svg.drawn.values === values && svg.drawn.cursor === cursor) return svg.drawn.frame;
  svg.replaceChildren();
  const frame = new Frame(svg, ts[0], ts[ts.length - 1], 0, 1, 24, false);
  el("line", { class: "axis", x1: frame.x([ts[0], 0]), y1: frame.y([0, 0]), x2: frame.x([ts[ts.length - 1], 0]), y2: frame.y([0, 0]) }, svg);
  el("line", { class: "axis", x1: frame.x([ts[0], 0]), y1: frame.y([0, 0]), x2: frame.x([ts[0], 0]), y2: frame.y([0, 1]) }, svg);
  const l1 = el("text", { class: "label", x: frame.x([ts[0], 1]) - 16, y: frame.y([0, 1]) + 4 }, svg);
  l1.textContent = "1";
  const count = values.length ? values[0].length : 0;
  for (let i = 0; i < count; i++) {
    const pts = ts.map((t, j) => [t, values[j][i]]);
    el("path", { class: "basis-fn", d: frame.path(pts), stroke: PALETTE[i % PALETTE.length], "data-index": i }, svg);
  }
  if (cursor !== undefined) {
    el("line", { class: "cursor", x1: frame.x([cursor, 0]), y1: frame.y([0, 0]), x2: frame.x([cursor, 0]), y2: frame.y([0, 1]) }, svg);
  }
  if (extra) extra(frame);
  svg.drawn = { values, cursor, frame };
  return frame;
}

// ---------------------------------------------------------------------------------------
// View 1: de Casteljau's construction.

const HODOGRAPH_ORIGIN = [4.5, 2.2];  // where the de Casteljau view draws the hodograph from

const bezier = {
  points: [
    [0.5, 0.5],
    [1.5, 4.2],
    [4.5, 4.6],
    [7.2, 3.4],
    [8.5, 0.4],
  ],
  t: 0.4,
  frame: null,

  init() {
    this.svg = document.getElementById("bz-canvas");
    this.basisSvg = document.getElementById("bz-basis");
    this.frame = new Frame(this.svg, -0.5, 9.5, -0.5, 5.5);
    this.tInput = document.getElementById("bz-t");
    this.update = coalesced(() => this.compute());
    this.tInput.addEventListener("input", () => {
      this.t = Number(this.tInput.value);
      this.update();
    });
    for (const id of ["bz-construction", "bz-hull", "bz-split", "bz-elevate", "bz-hodograph", "bz-portion", "bz-s"]) {
      document.getElementById(id).addEventListener("input", () => this.update());
    }
    document.getElementById("bz-add").addEventListener("click", () => {
      if (this.points.length >= 11) return;  // degree <= 10
      const a = this.points[this.points.length - 2], b = this.points[this.points.length - 1];
      this.points.push([Math.min(9.3, b[0] + (b[0] - a[0]) * 0.5), Math.max(-0.3, Math.min(5.3, b[1] + 0.8))]);
      this.update();
    });
    document.getElementById("bz-remove").addEventListener("click", () => {
      if (this.points.length > 2) this.points.pop();
      this.update();
    });
  },

  curve() {
    return { type: "bezier", points: this.points };
  },

  // De Casteljau's intermediate points b_i^k(t) (k = 1..n, i = 0..n-k): b_i^k is the Bézier
  // curve on P_i..P_(i+k) at t, so one eval of a path made of those sub-curves, segment j
  // asked at j + t, answers them all. Each query stays inside its own segment, clear of the
  // next one's start: for t >= 1/2 the sub-curves are reversed and asked at 1 - t.
  constructionRequest() {
    const n = this.points.length - 1;
    const reversed = this.t >= 0.5;
    const s = reversed ? 1 - this.t : this.t;
    const segments = [], ts = [], index = [];
    for (let k = 1; k <= n; k++) {
      for (let i = 0; i + k <= n; i++) {
        const sub = this.points.slice(i, i + k + 1);
        segments.push({ type: "bezier", points: reversed ? sub.reverse() : sub });
        ts.push(segments.length - 1 + s);
        index.push([k, i]);
      }
    }
    return { request: { curve: { type: "path", segments }, t: ts }, index };
  },

  async compute() {
    const n = this.points.length - 1;
    const curve = this.curve();
    const elevateTimes = Number(document.getElementById("bz-elevate").value) || 0;
    const ts = linspace(0, 1, 161);
    const construction = this.constructionRequest();
    const jobs = [
      api("eval", { curve, t: ts }),
      api("eval", { curve, t: [this.t], derivatives: 1, curvature: true }),
      api("eval", construction.request),
      api("split", { curve, t: this.t }),
      elevateTimes > 0 ? api("elevate", { curve, times: elevateTimes }) : null,
      apiKept("basis", { kind: "bernstein", degree: n, t: ts }),
      apiKept("basis", { kind: "bernstein", degree: n, t: [this.t] }),
      api("length", { curve }),
      document.getElementById("bz-hodograph").checked ? api("eval", { curve, t: ts, derivatives: 1 }) : null,
    ];
    const [samples, at, levels, halves, elevated, basis, basisAt, length, hodograph] = await Promise.all(jobs);
    // The portion over [s, t] (or [t, s]): split at the larger, then its left part at the
    // smaller's place in it. Its control points are the blossom's values b(a..a b..b).
    let portion = null;
    const sv = Number(document.getElementById("bz-s").value);
    const a = Math.min(sv, this.t), b = Math.max(sv, this.t);
    if (document.getElementById("bz-portion").checked && b > 0 && a < b) {
      const left = b < 1 ? halves.curves[0] : curve;
      const first = this.t === b ? left : (await api("split", { curve, t: b })).curves[0];
      portion = a > 0 ? (await api("split", { curve: first, t: a / b })).curves[1] : first;
    }
    this.draw({ samples, at, levels, construction, halves, elevated, basis, basisAt, length, hodograph, portion, a, b, ts });
  },

  draw(r) {
    const f = this.frame, svg = this.svg;
    redraw(svg);
    const show = (id) => document.getElementById(id).checked;
    if (show("bz-hull")) el("polygon", { class: "hull", id: "bz-hull-shape", points: convexHull(this.points).map((p) => f.x(p) + "," + f.y(p)).join(" ") }, svg);
    el("path", { class: "polygon", d: f.path(this.points) }, svg);
    const curve = el("path", { class: "curve", id: "bz-curve", d: f.path(r.samples.points) }, svg);
    curve.dataset.points = JSON.stringify(r.samples.points);
    if (show("bz-construction")) {
      const n = this.points.length - 1;
      const byLevel = [];
      r.construction.index.forEach(([k, i], j) => {
        (byLevel[k] ||= [])[i] = r.levels.points[j];
      });
      for (let k = 1; k < n; k++) {
        const color = PALETTE[(k - 1) % PALETTE.length];
        el("path", { class: "level", d: f.path(byLevel[k]), stroke: color, "data-level": k }, svg);
        for (const p of byLevel[k]) el("circle", { class: "level-point", cx: f.x(p), cy: f.y(p), r: 3.5, fill: color }, svg);
      }
    }
    if (show("bz-split")) {
      const [left, right] = r.halves.curves;
      el("path", { class: "half-left", id: "bz-left", d: f.path(left.points) }, svg);
      el("path", { class: "half-right", id: "bz-right", d: f.path(right.points) }, svg);
    }
    if (r.elevated) {
      const pts = r.elevated.curve.points;
      el("path", { class: "elevated", id: "bz-elevated", d: f.path(pts) }, svg);
      for (const p of pts) el("circle", { class: "elevated-point", cx: f.x(p), cy: f.y(p), r: 3 }, svg);
    }
    const c = r.at.points[0];
    if (r.portion) {
      const pts = r.portion.points, n = pts.length - 1;
      const e = el("path", { class: "half-right", id: "bz-portion-polygon", d: f.path(pts) }, svg);
      e.dataset.points = JSON.stringify(pts);
      pts.forEach((p, i) => {
        el("circle", { class: "elevated-point", cx: f.x(p), cy: f.y(p), r: 3.5 }, svg);
        const args = Array(n - i).fill("a").concat(Array(i).fill("b")).join("");
        const label = el("text", { class: "label", x: f.x(p) + 6, y: f.y(p) + 16 }, svg);
        label.textContent = "b(" + args + ")";
      });
    }
    if (r.hodograph) {
      // The hodograph C'(s) / n (a Bézier curve on the differences of the points), drawn
      // from the origin mark, and C'(t) / n both there and at C(t) (the server's eval).
      const n = this.points.length - 1, o = HODOGRAPH_ORIGIN;
      const at = (v) => [o[0] + v[0] / n, o[1] + v[1] / n];
      const hodo = r.hodograph.derivatives[0].map(at);
      const e = el("path", { class: "elevated", id: "bz-hodograph-curve", d: f.path(hodo) }, svg);
      e.dataset.points = JSON.stringify(r.hodograph.derivatives[0]);
      el("path", { d: `M${f.x(o) - 6} ${f.y(o)}h12M${f.x(o)} ${f.y(o) - 6}v12`, stroke: "#555", "stroke-width": 1.5 }, svg);
      const d = r.at.derivatives[0][0], tip = at(d), onCurve = [c[0] + d[0] / n, c[1] + d[1] / n];
      el("line", { class: "cursor", x1: f.x(o), y1: f.y(o), x2: f.x(tip), y2: f.y(tip), style: "stroke: #d35400; stroke-width: 2" }, svg);
      el("line", { class: "cursor", x1: f.x(c), y1: f.y(c), x2: f.x(onCurve), y2: f.y(onCurve), style: "stroke: #d35400; stroke-width: 2" }, svg);
    }
    el("circle", { class: "on-curve", id: "bz-on-curve", cx: f.x(c), cy: f.y(c), r: 6 }, svg);
    this.points.forEach((p, i) => {
      const h = el("circle", { class: "handle", cx: f.x(p), cy: f.y(p), r: 9, "data-index": i, "data-point": JSON.stringify(p) }, svg);
      dragHandle(f, h, i, (index, w) => {
        this.points[index] = w;
        this.update();
      });
      const label = el("text", { class: "label", x: f.x(p) + 11, y: f.y(p) - 11 }, svg);
      label.textContent = "P" + i;
    });
    // Numbers.
    document.getElementById("bz-t-out").textContent = fmt(this.t);
    document.getElementById("bz-s-out").textContent = "a = " + fmt(r.a) + ", b = " + fmt(r.b);
    document.getElementById("bz-degree").textContent = String(this.points.length - 1);
    document.getElementById("bz-point").textContent = fmtPoint(c);
    document.getElementById("bz-point").dataset.value = JSON.stringify(c);
    document.getElementById("bz-tangent").textContent = fmtPoint(r.at.derivatives[0][0]);
    document.getElementById("bz-curvature").textContent = fmt(r.at.curvature[0]);
    document.getElementById("bz-length").textContent = fmt(r.length.length);
    document.getElementById("bz-bernstein").textContent = r.basisAt.values[0].map(fmt).join(", ");
    const list = document.getElementById("bz-points");
    list.replaceChildren(...this.points.map((p) => Object.assign(document.createElement("li"), { textContent: fmtPoint(p) })));
    drawBasis(this.basisSvg, r.ts, r.basis.values, this.t);
  },
};

// ---------------------------------------------------------------------------------------
// View 3: B-splines and NURBS.

function clampedUniform(count, degree) {
  const inner = count - degree - 1;
  const knots = [];
  for (let i = 0; i <= degree; i++) knots.push(0);
  for (let i = 1; i <= inner; i++) knots.push(i / (inner + 1));
  for (let i = 0; i <= degree; i++) knots.push(1);
  return knots;
}

const DEFAULT_BSPLINE = [
  [0.3, 0.6],
  [1.2, 4.0],
  [3.2, 4.8],
  [4.6, 1.0],
  [6.3, 0.8],
  [7.4, 4.5],
  [9.0, 3.0],
];

const bspline = {
  degree: 3,
  points: DEFAULT_BSPLINE.map((p) => p.slice()),
  weights: DEFAULT_BSPLINE.map(() => 1),
  knots: clampedUniform(DEFAULT_BSPLINE.length, 3),
  u: 0.5,
  center: null,  // the exact circle's centre, while it is shown

  init() {
    this.svg = document.getElementById("bs-canvas");
    this.basisSvg = document.getElementById("bs-basis");
    this.frame = new Frame(this.svg, -0.5, 9.5, -0.5, 5.5);
    this.update = coalesced(() => this.compute());
    this.uInput = document.getElementById("bs-u");
    this.uInput.addEventListener("input", () => {
      this.u = this.domain()[0] + Number(this.uInput.value) * (this.domain()[1] - this.domain()[0]);
      this.update();
    });
    document.getElementById("bs-deboor").addEventListener("input", () => this.update());
    document.getElementById("bs-degree").addEventListener("change", (e) => {
      const p = Number(e.target.value);
      if (p >= this.points.length) return;
      this.degree = p;
      this.knots = clampedUniform(this.points.length, p);
      this.center = null;
      this.update();
    });
    document.getElementById("bs-uniform").addEventListener("click", () => {
      this.knots = clampedUniform(this.points.length, this.degree);
      this.update();
    });
    document.getElementById("bs-reset").addEventListener("click", () => {
      this.degree = 3;
      document.getElementById("bs-degree").value = "3";
      this.points = DEFAULT_BSPLINE.map((p) => p.slice());
      this.weights = this.points.map(() => 1);
      this.knots = clampedUniform(this.points.length, 3);
      this.center = null;
      this.frame.set(-0.5, 9.5, -0.5, 5.5);
      this.renderPointList();
      this.update();
    });
    document.getElementById("bs-insert").addEventListener("click", () => this.insertKnot());
    document.getElementById("bs-remove").addEventListener("click", () => this.removeKnot());
    document.getElementById("bs-tol").addEventListener("input", () => this.update());
    document.getElementById("bs-circle").addEventListener("click", () => this.circle());
    this.renderPointList();
  },

  domain() {
    return [this.knots[this.degree], this.knots[this.points.length]];
  },

  rational() {
    return this.weights.some((w) => w !== 1);
  },

  curve() {
    const c = { type: this.rational() ? "nurbs" : "bspline", degree: this.degree, knots: this.knots, points: this.points };
    if (this.rational()) c.weights = this.weights;
    return c;
  },

  load(curve) {
    this.degree = curve.degree;
    this.knots = curve.knots;
    this.points = curve.points;
    this.weights = curve.weights || curve.points.map(() => 1);
    document.getElementById("bs-degree").value = String(this.degree);
    this.renderPointList();
  },

  async insertKnot() {
    try {
      const r = await api("insert_knot", { curve: this.curve(), knot: this.u });
      this.load(r.curve);
      this.update();
    } catch (e) {
      status.textContent = e.message;
    }
  },

  // Removes the interior knot nearest u, all its copies if the tolerance allows
  // (remove_knot keeps each removal only while the curve moves by at most the tolerance).
  async removeKnot() {
    const p = this.degree, n = this.points.length;
    const interior = this.knots.slice(p + 1, n);
    const out = document.getElementById("bs-removed");
    if (!interior.length) {
      out.textContent = "no interior knot";
      return;
    }
    const knot = interior.reduce((a, b) => (Math.abs(b - this.u) < Math.abs(a - this.u) ? b : a));
    const times = interior.filter((k) => k === knot).length;
    const tolerance = this.tolerance();
    try {
      const r = await api("remove_knot", { curve: this.curve(), knot, times, tolerance });
      out.textContent = "u = " + fmt(knot) + ": " + r.removed + " of " + times + (times === 1 ? " copy" : " copies") + " removed within " + tolerance.toExponential(1);
      out.dataset.request = JSON.stringify({ knot, times, tolerance });
      this.load(r.curve);
      this.update();
    } catch (e) {
      status.textContent = e.message;
    }
  },

  tolerance() {
    return Math.pow(10, Number(document.getElementById("bs-tol").value));
  },

  // The exact circle: the server's NURBS for the circle shorthand (to_bspline answers it).
  async circle() {
    try {
      this.center = [4.5, 2.5];
      const r = await api("to_bspline", { curve: { type: "circle", center: this.center, radius: 2 } });
      this.load(r.curve);
      this.update();
    } catch (e) {
      status.textContent = e.message;
    }
  },

  // One row per control point: its coordinates and its weight's slider.
  renderPointList() {
    const list = document.getElementById("bs-points");
    list.replaceChildren();
    this.points.forEach((p, i) => {
      const li = document.createElement("li");
      const coords = document.createElement("span");
      coords.className = "coords";
      const slider = Object.assign(document.createElement("input"), { type: "range", min: "0.05", max: "5", step: "0.01", value: String(this.weights[i]) });
      slider.id = "bs-weight-" + i;
      slider.setAttribute("aria-label", "weight of point " + i);
      const out = document.createElement("output");
      slider.addEventListener("input", () => {
        this.weights[i] = Number(slider.value);
        this.update();
      });
      li.append(coords, " w ", slider, " ", out);
      list.appendChild(li);
    });
  },

  async compute() {
    const curve = this.curve();
    const [a, b] = this.domain();
    this.u = Math.min(b, Math.max(a, this.u));
    const ts = linspace(a, b, 241);
    const deBoor = this.deBoorRequests(curve);
    const [samples, at, basis, ...inserted] = await Promise.all([
      api("eval", { curve, t: ts }),
      api("eval", { curve, t: [this.u] }),
      apiKept("basis", { kind: "bspline", degree: this.degree, knots: this.knots, t: ts }),
      ...deBoor.requests.map((r) => api("insert_knot", r)),
    ]);
    const levels = [this.points.slice(deBoor.k - this.degree, deBoor.k - deBoor.s + 1)];
    inserted.forEach((r, i) => levels.push(r.curve.points.slice(deBoor.k - this.degree + i + 1, deBoor.k - deBoor.s + 1)));
    this.draw({ samples, at, basis, ts, levels: deBoor.requests.length ? levels : [] });
  },

  // De Boor's construction at u: inserting u r times (r = 1 .. p - s, s its multiplicity)
  // puts the construction's level r among the new control points, at indices k - p + r ..
  // k - s (k the knot span of u; the NURBS Book, section 5.2): the server's insert_knot
  // answers every level. None at the domain's ends or where u is a knot of multiplicity p.
  deBoorRequests(curve) {
    const p = this.degree, n = this.points.length, U = this.knots, u = this.u;
    const none = { requests: [], k: p, s: 0 };
    if (!document.getElementById("bs-deboor").checked || !(u > U[p] && u < U[n])) return none;
    let k = p;
    while (k + 1 < n && U[k + 1] <= u) k++;
    const s = U.filter((x) => x === u).length;
    if (s >= p) return none;
    const requests = [];
    for (let r = 1; r <= p - s; r++) requests.push({ curve, knot: u, times: r });
    return { requests, k, s };
  },

  draw(r) {
    const f = this.frame, svg = this.svg;
    redraw(svg);
    el("path", { class: "polygon", d: f.path(this.points) }, svg);
    const curve = el("path", { class: "curve", id: "bs-curve", d: f.path(r.samples.points) }, svg);
    curve.dataset.points = JSON.stringify(r.samples.points);
    r.levels.forEach((level, k) => {
      const color = k === 0 ? "#999" : PALETTE[(k - 1) % PALETTE.length];
      const e = el("path", { class: "level", d: f.path(level), stroke: color, "data-level": k }, svg);
      e.dataset.points = JSON.stringify(level);
      for (const q of level) el("circle", { class: "level-point", cx: f.x(q), cy: f.y(q), r: 3.5, fill: color }, svg);
    });
    const c = r.at.points[0];
    el("circle", { class: "on-curve", id: "bs-on-curve", cx: f.x(c), cy: f.y(c), r: 6 }, svg);
    this.points.forEach((p, i) => {
      const h = el("circle", { class: "handle", cx: f.x(p), cy: f.y(p), r: 9, "data-index": i, "data-point": JSON.stringify(p) }, svg);
      dragHandle(f, h, i, (index, w) => {
        this.points[index] = w;
        this.center = null;
        this.update();
      });
      const label = el("text", { class: "label", x: f.x(p) + 11, y: f.y(p) - 11 }, svg);
      label.textContent = "P" + i + (this.weights[i] !== 1 ? " (w " + this.weights[i].toFixed(3) + ")" : "");
    });
    // The basis functions over the knot vector, the knots draggable on its axis.
    const [a, b] = this.domain();
    const p = this.degree, n = this.points.length;
    drawBasis(this.basisSvg, r.ts, r.basis.values, this.u, (bf) => {
      this.knots.forEach((k, i) => {
        if (k < a || k > b) return;
        const interior = i > p && i < n;
        const mark = el("circle", { class: "knot" + (interior ? "" : " fixed"), cx: bf.x([k, 0]), cy: bf.y([0, 0]), r: interior ? 7 : 5, "data-knot": i }, this.basisSvg);
        if (interior) {
          dragHandle(bf, mark, i, (index, w) => {
            // Knots stay non-decreasing: between their neighbours.
            this.knots[index] = Math.min(this.knots[index + 1], Math.max(this.knots[index - 1], w[0]));
            this.update();
          });
        }
      });
    });
    // Numbers.
    document.getElementById("bs-u-out").textContent = fmt(this.u);
    document.getElementById("bs-tol-out").textContent = this.tolerance().toExponential(1);
    document.getElementById("bs-type").textContent = (this.rational() ? "NURBS" : "B-spline") + ", degree " + p + ", " + n + " points";
    document.getElementById("bs-point").textContent = fmtPoint(c);
    document.getElementById("bs-point").dataset.value = JSON.stringify(c);
    document.getElementById("bs-domain").textContent = "[" + fmt(a) + ", " + fmt(b) + "]";
    document.getElementById("bs-knots").textContent = this.knots.map(fmt).join(", ");
    document.getElementById("bs-radius").textContent = this.center ? fmt(Math.hypot(c[0] - this.center[0], c[1] - this.center[1])) : "—";
    const rows = document.getElementById("bs-points").children;
    this.points.forEach((q, i) => {
      if (!rows[i]) return;
      rows[i].querySelector(".coords").textContent = fmtPoint(q);
      rows[i].querySelector("output").textContent = this.weights[i].toFixed(3);
      rows[i].querySelector("input").value = String(this.weights[i]);
    });
  },
};

// ---------------------------------------------------------------------------------------
// View 4: interpolation.

// Runge's bump 1 / (1 + 25 x^2) on [-1, 1], at 9 equally spaced x, drawn on the canvas.
const RUNGE = linspace(-1, 1, 9).map((x) => [4.5 + 4 * x, 0.5 + 4 * (1 / (1 + 25 * x * x))]);

// The parameters of a Lagrange curve through n points: equally spaced, or the Chebyshev
// nodes (of the first kind) on the same interval [0, n - 1], increasing.
function chebyshevParams(n) {
  const out = [];
  for (let i = 0; i < n; i++) out.push(((n - 1) / 2) * (1 - Math.cos(((2 * i + 1) * Math.PI) / (2 * n))));
  return out;
}

const INTERPOLANTS = [
  { key: "lagrange_uniform", label: "Lagrange, equally spaced parameters", color: "#d62728", on: true,
    curve: (p) => ({ type: "lagrange", params: p.map((_, i) => i), points: p }) },
  { key: "lagrange_chebyshev", label: "Lagrange, Chebyshev parameters", color: "#2ca02c", on: true,
    curve: (p) => ({ type: "lagrange", params: chebyshevParams(p.length), points: p }) },
  { key: "spline_natural", label: "cubic spline, natural (chord)", color: "#1f77b4", on: true,
    curve: (p) => ({ type: "cubic_spline", parametrization: "chord", boundary: "natural", points: p }) },
  { key: "spline_not_a_knot", label: "cubic spline, not-a-knot (chord)", color: "#17becf", on: false,
    curve: (p) => ({ type: "cubic_spline", parametrization: "chord", boundary: "not-a-knot", points: p }) },
  { key: "spline_clamped", label: "cubic spline, clamped (end tangents (1, 0), chord)", color: "#e377c2", on: false,
    curve: (p) => ({ type: "cubic_spline", parametrization: "chord", boundary: "clamped", start_derivative: [1, 0], end_derivative: [1, 0], points: p }) },
  { key: "spline_periodic", label: "cubic spline, periodic (closed through the first point, chord)", color: "#bcbd22", on: false,
    curve: (p) => ({ type: "cubic_spline", parametrization: "chord", boundary: "periodic", points: [...p, p[0]] }) },
  { key: "catmull_rom_0", label: "Catmull-Rom, uniform (α 0)", color: "#ff7f0e", on: false,
    curve: (p) => ({ type: "catmull_rom", alpha: 0, ends: "reflect", points: p }) },
  { key: "catmull_rom_05", label: "Catmull-Rom, centripetal (α 0.5)", color: "#9467bd", on: false,
    curve: (p) => ({ type: "catmull_rom", alpha: 0.5, ends: "reflect", points: p }) },
  { key: "catmull_rom_1", label: "Catmull-Rom, chordal (α 1)", color: "#8c564b", on: false,
    curve: (p) => ({ type: "catmull_rom", alpha: 1, ends: "reflect", points: p }) },
];

const interpolation = {
  points: RUNGE.map((p) => p.slice()),

  init() {
    this.svg = document.getElementById("ip-canvas");
    this.frame = new Frame(this.svg, -0.5, 9.5, -0.5, 5.5);
    this.update = coalesced(() => this.compute());
    const box = document.getElementById("ip-choices");
    for (const c of INTERPOLANTS) {
      const label = document.createElement("label");
      const input = Object.assign(document.createElement("input"), { type: "checkbox", checked: c.on, id: "ip-" + c.key });
      input.addEventListener("input", () => this.update());
      const swatch = Object.assign(document.createElement("span"), { textContent: "■ " });
      swatch.style.color = c.color;
      label.append(input, " ", swatch, c.label);
      box.appendChild(label);
    }
  },

  chosen() {
    return INTERPOLANTS.filter((c) => document.getElementById("ip-" + c.key).checked);
  },

  async compute() {
    const chosen = this.chosen();
    const answers = await Promise.all(
      chosen.map(async (c) => {
        const curve = c.curve(this.points);
        const [flat, length] = await Promise.all([api("flatten", { curve, tolerance: 0.002 }), api("length", { curve })]);
        return { c, points: flat.points, length: length.length };
      }),
    );
    this.draw(answers);
  },

  draw(answers) {
    const f = this.frame, svg = this.svg;
    redraw(svg);
    for (const a of answers) {
      const e = el("path", { class: "curve", id: "ip-curve-" + a.c.key, d: f.path(a.points), style: "stroke: " + a.c.color + "; stroke-width: 2" }, svg);
      e.dataset.points = JSON.stringify(a.points);
    }
    pointHandles(this, f, svg, 7);
    const dl = document.getElementById("ip-lengths");
    dl.replaceChildren();
    for (const a of answers) {
      const dt = Object.assign(document.createElement("dt"), { textContent: a.c.label });
      const dd = Object.assign(document.createElement("dd"), { textContent: fmt(a.length), id: "ip-length-" + a.c.key });
      dl.append(dt, dd);
    }
  },
};

// ---------------------------------------------------------------------------------------
// View 5: subdivision curves.

const subdivision = {
  points: [
    [1.0, 0.8],
    [4.5, 0.3],
    [8.2, 1.2],
    [7.0, 4.6],
    [4.6, 2.6],
    [1.8, 4.9],
  ],

  init() {
    this.svg = document.getElementById("sd-canvas");
    this.frame = new Frame(this.svg, -0.5, 9.5, -0.5, 5.5);
    this.update = coalesced(() => this.compute());
    for (const id of ["sd-scheme", "sd-degree", "sd-tension", "sd-steps", "sd-closed", "sd-previous", "sd-limit"]) {
      document.getElementById(id).addEventListener("input", () => this.update());
    }
  },

  request(iterations) {
    const scheme = document.getElementById("sd-scheme").value;
    const r = { points: this.points, scheme, iterations, closed: document.getElementById("sd-closed").checked };
    if (scheme === "lane_riesenfeld") r.degree = Number(document.getElementById("sd-degree").value) || 1;
    if (scheme === "four_point") r.tension = Number(document.getElementById("sd-tension").value);
    return r;
  },

  async compute() {
    const k = Number(document.getElementById("sd-steps").value);
    const [now, before, deep] = await Promise.all([
      api("subdivide", this.request(k)),
      k > 0 ? api("subdivide", this.request(k - 1)) : null,
      api("subdivide", this.request(7)),
    ]);
    let limit = null;
    if (deep.limit) {
      const c = deep.limit, p = c.degree, n = c.points.length;
      const ts = linspace(c.knots[p], c.knots[n], 401);
      limit = { curve: c, points: (await api("eval", { curve: c, t: ts })).points };
    }
    this.draw({ k, now, before, deep, limit });
  },

  draw(r) {
    const f = this.frame, svg = this.svg;
    redraw(svg);
    const closed = document.getElementById("sd-closed").checked;
    const ring = (pts) => (closed && pts.length ? pts.concat([pts[0]]) : pts);
    el("path", { class: "polygon", d: f.path(ring(this.points)) }, svg);
    if (document.getElementById("sd-limit").checked) {
      const pts = r.limit ? r.limit.points : ring(r.deep.points);
      const e = el("path", { class: "curve", id: "sd-limit-curve", d: f.path(pts) }, svg);
      e.dataset.points = JSON.stringify(pts);
    }
    if (r.before && document.getElementById("sd-previous").checked) {
      el("path", { class: "level", stroke: "#aaa", d: f.path(ring(r.before.points)) }, svg);
    }
    const step = el("path", { class: "level", id: "sd-step", stroke: "#d35400", d: f.path(ring(r.now.points)) }, svg);
    step.dataset.points = JSON.stringify(r.now.points);
    for (const p of r.now.points) el("circle", { class: "level-point", cx: f.x(p), cy: f.y(p), r: 2.5, fill: "#d35400" }, svg);
    pointHandles(this, f, svg, 9);
    document.getElementById("sd-steps-out").textContent = String(r.k);
    document.getElementById("sd-tension-out").textContent = Number(document.getElementById("sd-tension").value).toFixed(4);
    document.getElementById("sd-count").textContent = String(r.now.points.length);
    document.getElementById("sd-limit-info").textContent = r.limit
      ? "uniform B-spline, degree " + r.limit.curve.degree + ", " + r.limit.curve.points.length + " control points" + (closed ? " (periodic)" : "")
      : "no closed form: the polygon after 7 steps (" + r.deep.points.length + " points)";
  },
};

// ---------------------------------------------------------------------------------------
// View 6: queries.

const queries = {
  a: [
    [0.5, 0.8],
    [2.2, 4.8],
    [6.0, 0.2],
    [9.0, 4.0],
  ],
  b: [
    [0.5, 4.5],
    [3.0, 0.2],
    [6.0, 5.2],
    [9.0, 0.8],
  ],
  mouse: null,

  init() {
    this.svg = document.getElementById("qr-canvas");
    this.frame = new Frame(this.svg, -0.5, 9.5, -0.5, 5.5);
    this.update = coalesced(() => this.compute());
    for (const id of ["qr-tol", "qr-method", "qr-bounds", "qr-flat", "qr-features"]) document.getElementById(id).addEventListener("input", () => this.update());
    document.getElementById("qr-piece").addEventListener("click", async () => {
      try {
        const right = (await api("split", { curve: { type: "bezier", points: this.a }, t: 0.25 })).curves[1];
        this.b.splice(0, 4, ...(await api("split", { curve: right, t: 0.5 })).curves[0].points);
        this.update();
      } catch (e) {
        status.textContent = e.message;
      }
    });
    this.svg.addEventListener("pointermove", (e) => {
      if (e.buttons) return;  // a drag: the handles' business
      // The figure's screen matrix kept until the page scrolls or resizes (see world()).
      if (!this.screen) {
        this.screen = this.svg.getScreenCTM().inverse();
        const forget = () => (this.screen = null);
        for (const type of ["scroll", "resize"]) window.addEventListener(type, forget, { once: true, capture: true });
      }
      this.mouse = this.frame.world(e, this.screen);
      this.update();
    });
  },

  tolerance() {
    return Math.pow(10, Number(document.getElementById("qr-tol").value));
  },

  async compute() {
    const A = { type: "bezier", points: this.a }, B = { type: "bezier", points: this.b };
    const ts = linspace(0, 1, 161);
    const tolerance = this.tolerance();
    const methods = ["optimal", "subdivision", "uniform"];
    const [sa, sb, inter, box, length, closest, ...flats] = await Promise.all([
      api("eval", { curve: A, t: ts }),
      api("eval", { curve: B, t: ts }),
      api("intersect", { curves: [A, B] }),
      api("bounds", { curve: A }),
      api("length", { curve: A }),
      this.mouse ? api("project", { curve: A, point: this.mouse }) : null,
      ...methods.map((method) => api("flatten", { curve: A, tolerance, method })),
    ]);
    const flat = {};
    methods.forEach((m, i) => (flat[m] = flats[i].points));
    // The features of A (inflections, cusps, the extrema of x and y) and the stretches where
    // A and B overlap, as points of A: one more batch, when shown.
    let features = null, marks = null, overlaps = [];
    if (document.getElementById("qr-features").checked) {
      features = await api("features", { curve: A });
      const kinds = [["inflection", features.inflections], ["cusp", features.cusps], ["extremum of x", features.extrema[0]], ["extremum of y", features.extrema[1]]];
      const ts = kinds.flatMap(([, t]) => t);
      const [at, ...spans] = await Promise.all([
        ts.length ? api("eval", { curve: A, t: ts }) : { points: [] },
        ...inter.overlaps.map((o) => api("eval", { curve: A, t: linspace(o.a[0], o.a[1], 33) })),
      ]);
      let k = 0;
      marks = kinds.flatMap(([kind, t]) => t.map((u) => ({ kind, t: u, point: at.points[k++] })));
      overlaps = spans.map((x) => x.points);
    }
    this.draw({ sa, sb, inter, box, length, closest, flat, marks, overlaps });
  },

  draw(r) {
    const f = this.frame, svg = this.svg;
    redraw(svg);
    if (document.getElementById("qr-bounds").checked) {
      // The control points' box (a drawing aid, as the convex hull: the cheap bound that
      // the tight one improves on), then the server's tight box.
      const xs = this.a.map((p) => p[0]), ys = this.a.map((p) => p[1]);
      const lo = [Math.min(...xs), Math.min(...ys)], hi = [Math.max(...xs), Math.max(...ys)];
      el("rect", { class: "hull", id: "qr-control-box", x: f.x(lo), y: f.y(hi), width: f.x(hi) - f.x(lo), height: f.y(lo) - f.y(hi), style: "fill: none; stroke-dasharray: 2 4" }, svg);
      const [x0, y0] = r.box.min, [x1, y1] = r.box.max;
      const rect = el("rect", { class: "polygon", id: "qr-bounds-box", x: f.x([x0, 0]), y: f.y([0, y1]), width: f.x([x1, 0]) - f.x([x0, 0]), height: f.y([0, y0]) - f.y([0, y1]) }, svg);
      rect.dataset.box = JSON.stringify(r.box);
    }
    el("path", { class: "polygon", d: f.path(this.a) }, svg);
    el("path", { class: "polygon", d: f.path(this.b) }, svg);
    el("path", { class: "curve", id: "qr-curve-a", d: f.path(r.sa.points) }, svg);
    el("path", { class: "curve", id: "qr-curve-b", d: f.path(r.sb.points), style: "stroke: #2e8b57" }, svg);
    const method = document.getElementById("qr-method").value;
    if (document.getElementById("qr-flat").checked) {
      const pts = r.flat[method];
      el("path", { class: "level", stroke: "#d35400", d: f.path(pts) }, svg);
      for (const p of pts) el("circle", { class: "level-point", cx: f.x(p), cy: f.y(p), r: 2.5, fill: "#d35400" }, svg);
    }
    for (const [i, pts] of r.overlaps.entries()) el("path", { class: "overlap", "data-overlap": i, d: f.path(pts), stroke: "#e67e22", "stroke-width": 7, "stroke-opacity": 0.6, fill: "none" }, svg);
    if (r.marks) {
      const g = el("g", { id: "qr-features-marks" }, svg);
      g.dataset.marks = JSON.stringify(r.marks);
      const shapes = { inflection: "#8e44ad", cusp: "#c0392b", "extremum of x": "#2a9d5c", "extremum of y": "#2a9d5c" };
      for (const m of r.marks) {
        const [x, y] = [f.x(m.point), f.y(m.point)];
        if (m.kind === "inflection") el("path", { d: `M${x} ${y - 7}l6 11h-12z`, fill: shapes[m.kind] }, g);
        else el("path", { d: m.kind === "extremum of x" ? `M${x} ${y - 8}v16` : `M${x - 8} ${y}h16`, stroke: shapes[m.kind], "stroke-width": 3 }, g);
      }
    }
    const marks = el("g", { id: "qr-intersections" }, svg);
    marks.dataset.points = JSON.stringify(r.inter.intersections.map((x) => x.point));
    for (const x of r.inter.intersections) {
      const p = x.point;
      if (x.kind === "tangent") el("rect", { x: f.x(p) - 6, y: f.y(p) - 6, width: 12, height: 12, fill: "#e67e22" }, marks);
      else el("circle", { cx: f.x(p), cy: f.y(p), r: 6, fill: "none", stroke: "#c0392b", "stroke-width": 2.5 }, marks);
    }
    if (r.closest && this.mouse) {
      const p = r.closest.point;
      el("line", { class: "cursor", x1: f.x(this.mouse), y1: f.y(this.mouse), x2: f.x(p), y2: f.y(p) }, svg);
      el("circle", { class: "on-curve", cx: f.x(p), cy: f.y(p), r: 5 }, svg);
    }
    for (const [name, pts] of [["a", this.a], ["b", this.b]]) {
      pts.forEach((p, i) => {
        const h = el("circle", { class: "handle", cx: f.x(p), cy: f.y(p), r: 8, "data-curve": name, "data-index": i, "data-point": JSON.stringify(p) }, svg);
        dragHandle(f, h, i, (index, w) => {
          pts[index] = w;
          this.update();
        });
      });
    }
    document.getElementById("qr-tol-out").textContent = this.tolerance().toExponential(2);
    for (const m of ["optimal", "subdivision", "uniform"]) document.getElementById("qr-count-" + m).textContent = String(r.flat[m].length - 1);
    document.getElementById("qr-length").textContent = fmt(r.length.length);
    document.getElementById("qr-box").textContent = fmtPoint(r.box.min) + " – " + fmtPoint(r.box.max);
    document.getElementById("qr-intersections-text").textContent = r.inter.intersections.length
      ? r.inter.intersections.map((x) => x.kind + " at t = (" + x.t.map(fmt).join(", ") + ")").join("; ")
      : "none";
    document.getElementById("qr-features-text").textContent = r.marks
      ? [["inflection", "inflections"], ["cusp", "cusps"], ["extremum of x", "extrema of x"], ["extremum of y", "extrema of y"]].map(([one, many]) => {
          const n = r.marks.filter((m) => m.kind === one).length;
          return n + " " + (n === 1 ? one : many);
        }).join(", ")
      : "—";
    document.getElementById("qr-overlaps").textContent = r.inter.overlaps.length ? r.inter.overlaps.map((o) => "A on [" + o.a.map(fmt).join(", ") + "]").join("; ") : "none";
    document.getElementById("qr-closest").textContent = r.closest ? "t = " + fmt(r.closest.t) + ", distance " + fmt(r.closest.distance) : "move the pointer over the figure";
  },
};

// ---------------------------------------------------------------------------------------
// View 2: composite curves (three cubic Bézier pieces, two joints).

// The continuity asked at a joint and what it moves: the points after the joint follow
// the points before it (a dependent point is drawn as a square and is not draggable).
const JOINT_KINDS = ["C0", "G1", "C1", "C2"];

const composite = {
  // Ten points: piece i is points 3i..3i+3; joints at points 3 and 6.
  points: [
    [0.4, 0.8], [1.2, 3.6], [2.6, 4.6], [3.6, 3.0], [4.2, 2.0], [4.6, 0.6],
    [6.0, 0.9], [7.2, 1.2], [7.8, 4.6], [9.0, 3.6],
  ],
  joints: ["C1", "C0"],
  combScale: 0.6,

  init() {
    this.svg = document.getElementById("cp-canvas");
    this.frame = new Frame(this.svg, -0.5, 9.5, -0.5, 5.5);
    this.update = coalesced(() => this.compute());
    this.joints.forEach((kind, j) => {
      const select = document.getElementById("cp-joint-" + j);
      select.value = kind;
      select.addEventListener("change", () => {
        this.joints[j] = select.value;
        this.enforce();
        this.update();
      });
    });
    const comb = document.getElementById("cp-comb-scale");
    comb.addEventListener("input", () => {
      this.combScale = Number(comb.value);
      this.update();
    });
    document.getElementById("cp-comb").addEventListener("input", () => this.update());
    this.enforce();
  },

  // The points set by the joints' continuity (index -> true).
  dependent() {
    const out = {};
    this.joints.forEach((kind, j) => {
      const m = 3 * (j + 1);
      if (kind !== "C0") out[m + 1] = true;
      if (kind === "C2") out[m + 2] = true;
    });
    return out;
  },

  // Moves the dependent points so that each joint has the continuity asked (cubic pieces
  // on parameter intervals of equal length: the end derivatives 3 (P3 - P2) and 6 (P3 -
  // 2 P2 + P1) of the left piece equal the right piece's 3 (Q1 - Q0) and 6 (Q2 - 2 Q1 + Q0)).
  enforce() {
    const P = this.points;
    this.joints.forEach((kind, j) => {
      const m = 3 * (j + 1);
      const d = [P[m][0] - P[m - 1][0], P[m][1] - P[m - 1][1]];
      if (kind === "G1") {
        const len = Math.hypot(P[m + 1][0] - P[m][0], P[m + 1][1] - P[m][1]) || 1;
        const dl = Math.hypot(d[0], d[1]) || 1;
        P[m + 1] = [P[m][0] + (len * d[0]) / dl, P[m][1] + (len * d[1]) / dl];
      } else if (kind === "C1" || kind === "C2") {
        P[m + 1] = [P[m][0] + d[0], P[m][1] + d[1]];
        if (kind === "C2") P[m + 2] = [P[m - 2][0] + 4 * d[0], P[m - 2][1] + 4 * d[1]];
      }
    });
  },

  pieces() {
    return [0, 1, 2].map((i) => ({ type: "bezier", points: this.points.slice(3 * i, 3 * i + 4) }));
  },

  async compute() {
    const pieces = this.pieces();
    const path = { type: "path", segments: pieces };
    const ts = linspace(0, 3, 241);
    const ends = [];
    for (let j = 0; j < 2; j++) {
      ends.push(api("eval", { curve: pieces[j], t: [1], derivatives: 2, curvature: true }));
      ends.push(api("eval", { curve: pieces[j + 1], t: [0], derivatives: 2, curvature: true }));
    }
    const [samples, ...sides] = await Promise.all([api("eval", { curve: path, t: ts, derivatives: 1, curvature: true }), ...ends]);
    this.draw({ samples, sides });
  },

  // The continuity reached at a joint, from the two pieces' end values (the server's):
  // the highest of C0, G1, C1, G2, C2 that holds to 1e-9 of the derivatives' size.
  continuity(left, right) {
    const close = (a, b) => {
      const scale = Math.max(1, Math.hypot(...a), Math.hypot(...b));
      return Math.hypot(...a.map((x, i) => x - b[i])) <= 1e-9 * scale;
    };
    const unit = (v) => {
      const n = Math.hypot(...v);
      return n > 0 ? v.map((x) => x / n) : v;
    };
    if (!close(left.points[0], right.points[0])) return "none";
    const d1l = left.derivatives[0][0], d1r = right.derivatives[0][0];
    const d2l = left.derivatives[1][0], d2r = right.derivatives[1][0];
    if (close(d1l, d1r)) {
      if (close(d2l, d2r)) return "C2";
      return Math.abs(left.curvature[0] - right.curvature[0]) <= 1e-9 * Math.max(1, Math.abs(left.curvature[0])) ? "G2 (C1)" : "C1";
    }
    if (!close(unit(d1l), unit(d1r))) return "C0";
    return Math.abs(left.curvature[0] - right.curvature[0]) <= 1e-9 * Math.max(1, Math.abs(left.curvature[0])) ? "G2" : "G1";
  },

  draw(r) {
    const f = this.frame, svg = this.svg;
    redraw(svg);
    for (let i = 0; i < 3; i++) el("path", { class: "polygon", d: f.path(this.points.slice(3 * i, 3 * i + 4)) }, svg);
    const pts = r.samples.points;
    // The curvature comb: at each sample a tooth of length scale x curvature along the
    // normal, away from the centre of curvature (the server's curvature and derivative).
    if (document.getElementById("cp-comb").checked) {
      const tips = pts.map((p, i) => {
        const d = r.samples.derivatives[0][i], k = r.samples.curvature[i];
        const n = Math.hypot(d[0], d[1]) || 1;
        const s = -this.combScale * k;
        return [p[0] + (s * -d[1]) / n, p[1] + (s * d[0]) / n];
      });
      const teeth = pts.map((p, i) => "M" + f.x(p).toFixed(2) + " " + f.y(p).toFixed(2) + "L" + f.x(tips[i]).toFixed(2) + " " + f.y(tips[i]).toFixed(2)).join("");
      el("path", { class: "comb", d: teeth }, svg);
      const envelope = el("path", { class: "comb-envelope", id: "cp-comb-envelope", d: f.path(tips) }, svg);
      envelope.dataset.curvature = JSON.stringify(r.samples.curvature);
    }
    const curve = el("path", { class: "curve", id: "cp-curve", d: f.path(pts) }, svg);
    curve.dataset.points = JSON.stringify(pts);
    const dep = this.dependent();
    this.points.forEach((p, i) => {
      if (dep[i]) {
        el("rect", { class: "dependent", x: f.x(p) - 6, y: f.y(p) - 6, width: 12, height: 12, "data-index": i, "data-point": JSON.stringify(p) }, svg);
        return;
      }
      const h = el("circle", { class: "handle" + (i % 3 === 0 ? " joint" : ""), cx: f.x(p), cy: f.y(p), r: 8, "data-index": i, "data-point": JSON.stringify(p) }, svg);
      dragHandle(f, h, i, (index, w) => {
        const P = this.points;
        // A joint's point carries its two neighbours along.
        if (index % 3 === 0 && index > 0 && index < 9) {
          const dx = w[0] - P[index][0], dy = w[1] - P[index][1];
          for (const k of [index - 1, index + 1]) P[k] = [P[k][0] + dx, P[k][1] + dy];
        }
        P[index] = w;
        this.enforce();
        this.update();
      });
    });
    for (let j = 0; j < 2; j++) {
      const left = r.sides[2 * j], right = r.sides[2 * j + 1];
      const reached = this.continuity(left, right);
      document.getElementById("cp-joint-" + j + "-reached").textContent = reached;
      document.getElementById("cp-joint-" + j + "-curvature").textContent = fmt(left.curvature[0]) + " | " + fmt(right.curvature[0]);
      const m = this.points[3 * (j + 1)];
      const label = el("text", { class: "label", x: f.x(m) + 10, y: f.y(m) + 22 }, svg);
      label.textContent = reached;
    }
    document.getElementById("cp-comb-scale-out").textContent = this.combScale.toFixed(2);
  },
};

// ---------------------------------------------------------------------------------------
// View 4b: Hermite curves and the tangent rules.

const TANGENT_SCALE = 0.5;  // a tangent m is drawn from P to P + 0.5 m

const TANGENT_RULES = [
  { key: "explicit", label: "Hermite, your tangents (drag the arrow heads)", color: "#1f5fbf", on: true },
  { key: "finite_difference", label: "finite differences", color: "#7f7f7f", on: false },
  { key: "catmull_rom", label: "Catmull-Rom", color: "#ff7f0e", on: true },
  { key: "cardinal", label: "cardinal (tension below)", color: "#9467bd", on: false },
  { key: "kochanek_bartels", label: "Kochanek-Bartels (T, C, B below)", color: "#8c564b", on: false },
  { key: "monotone", label: "PCHIP (monotone, as scipy)", color: "#2ca02c", on: true },
  { key: "akima", label: "Akima (as scipy)", color: "#d62728", on: true },
];

const hermite = {
  // A step: monotone data, where PCHIP keeps to the data's range and the others overshoot.
  points: [
    [0.5, 0.8], [2.0, 0.8], [3.4, 0.8], [4.6, 4.2], [6.6, 4.2], [8.6, 4.2],
  ],
  tangents: [
    [1, 0], [1, 0], [1, 1.5], [1, 1.5], [1, 0], [1, 0],
  ],

  init() {
    this.svg = document.getElementById("hm-canvas");
    this.frame = new Frame(this.svg, -0.5, 9.5, -0.5, 5.5);
    this.update = coalesced(() => this.compute());
    const box = document.getElementById("hm-choices");
    for (const c of TANGENT_RULES) {
      const label = document.createElement("label");
      const input = Object.assign(document.createElement("input"), { type: "checkbox", checked: c.on, id: "hm-" + c.key });
      input.addEventListener("input", () => this.update());
      const swatch = Object.assign(document.createElement("span"), { textContent: "■ " });
      swatch.style.color = c.color;
      label.append(input, " ", swatch, c.label);
      box.appendChild(label);
    }
    for (const id of ["hm-param", "hm-tension", "hm-kb-t", "hm-kb-c", "hm-kb-b"]) document.getElementById(id).addEventListener("input", () => this.update());
  },

  // The parameters: the points' x (the curve is then a function y(x), as scipy's
  // PchipInterpolator and Akima1DInterpolator see data), or a parametrization's name.
  parameters() {
    const mode = document.getElementById("hm-param").value;
    return mode === "x" ? { params: this.points.map((p) => p[0]) } : { parametrization: mode };
  },

  curve(key) {
    const c = { type: "hermite", ...this.parameters(), points: this.points };
    if (key === "explicit") return { ...c, tangents: this.tangents };
    c.tangent_rule = key;
    const v = (id) => Number(document.getElementById(id).value);
    if (key === "cardinal") c.tension = v("hm-tension");
    if (key === "kochanek_bartels") Object.assign(c, { tension: v("hm-kb-t"), continuity: v("hm-kb-c"), bias: v("hm-kb-b") });
    return c;
  },

  async compute() {
    const chosen = TANGENT_RULES.filter((c) => document.getElementById("hm-" + c.key).checked);
    const answers = await Promise.all(
      chosen.map(async (c) => {
        const curve = this.curve(c.key);
        const [flat, box] = await Promise.all([api("flatten", { curve, tolerance: 0.002 }), api("bounds", { curve })]);
        return { c, points: flat.points, box };
      }),
    );
    this.draw(answers);
  },

  draw(answers) {
    const f = this.frame, svg = this.svg;
    redraw(svg);
    for (const a of answers) {
      const e = el("path", { class: "curve", id: "hm-curve-" + a.c.key, d: f.path(a.points), style: "stroke: " + a.c.color + "; stroke-width: 2" }, svg);
      e.dataset.points = JSON.stringify(a.points);
    }
    const explicit = document.getElementById("hm-explicit").checked;
    const xmode = document.getElementById("hm-param").value === "x";
    this.points.forEach((p, i) => {
      if (explicit) {
        const m = this.tangents[i];
        const tip = [p[0] + TANGENT_SCALE * m[0], p[1] + TANGENT_SCALE * m[1]];
        el("line", { class: "tangent", x1: f.x(p), y1: f.y(p), x2: f.x(tip), y2: f.y(tip) }, svg);
        const t = el("circle", { class: "tangent-handle", cx: f.x(tip), cy: f.y(tip), r: 6, "data-index": i, "data-tangent": JSON.stringify(m) }, svg);
        dragHandle(f, t, i, (index, w) => {
          const q = this.points[index];
          this.tangents[index] = [(w[0] - q[0]) / TANGENT_SCALE, (w[1] - q[1]) / TANGENT_SCALE];
          this.update();
        });
      }
      const h = el("circle", { class: "handle", cx: f.x(p), cy: f.y(p), r: 8, "data-index": i, "data-point": JSON.stringify(p) }, svg);
      dragHandle(f, h, i, (index, w) => {
        // As a function y(x), the x stay increasing: between the neighbours'.
        if (xmode) {
          const lo = index > 0 ? this.points[index - 1][0] + 0.05 : -Infinity;
          const hi = index + 1 < this.points.length ? this.points[index + 1][0] - 0.05 : Infinity;
          w = [Math.min(hi, Math.max(lo, w[0])), w[1]];
        }
        this.points[index] = w;
        this.update();
      });
    });
    const ys = this.points.map((p) => p[1]);
    document.getElementById("hm-data-range").textContent = "[" + fmt(Math.min(...ys)) + ", " + fmt(Math.max(...ys)) + "]";
    const dl = document.getElementById("hm-ranges");
    dl.replaceChildren();
    for (const a of answers) {
      const dt = Object.assign(document.createElement("dt"), { textContent: a.c.label.split(" (")[0] });
      const dd = Object.assign(document.createElement("dd"), { textContent: "[" + fmt(a.box.min[1]) + ", " + fmt(a.box.max[1]) + "]", id: "hm-range-" + a.c.key });
      dl.append(dt, dd);
    }
    for (const id of ["hm-tension", "hm-kb-t", "hm-kb-c", "hm-kb-b"]) document.getElementById(id + "-out").textContent = Number(document.getElementById(id).value).toFixed(2);
  },
};

// ---------------------------------------------------------------------------------------
// View 4c: Catmull-Rom's alpha: uniform, centripetal, chordal.

const CATMULL_ALPHAS = [
  { alpha: 0, key: "0", label: "uniform (α 0)", color: "#ff7f0e" },
  { alpha: 0.5, key: "05", label: "centripetal (α 0.5)", color: "#9467bd" },
  { alpha: 1, key: "1", label: "chordal (α 1)", color: "#2ca02c" },
];

const catmull = {
  // Unevenly spaced points: the uniform curve loops (self-intersections), the centripetal
  // one does not (Yuksel, Schaefer and Keyser 2011).
  points: [
    [0.6, 4.3], [1.7, 1.4], [3.0, 2.3], [3.0, 2.0], [7.1, 2.2], [7.9, 1.5],
  ],

  init() {
    this.svg = document.getElementById("cr-canvas");
    this.frame = new Frame(this.svg, -0.5, 9.5, -0.5, 5.5);
    this.update = coalesced(() => this.compute());
    document.getElementById("cr-closed").addEventListener("input", () => this.update());
  },

  curve(alpha) {
    const closed = document.getElementById("cr-closed").checked;
    return closed ? { type: "catmull_rom", alpha, closed: true, points: this.points } : { type: "catmull_rom", alpha, ends: "reflect", points: this.points };
  },

  async compute() {
    const answers = await Promise.all(
      CATMULL_ALPHAS.map(async (c) => {
        const curve = this.curve(c.alpha);
        const [flat, self, features] = await Promise.all([
          api("flatten", { curve, tolerance: 0.002 }),
          api("intersect", { curves: [curve] }),
          api("features", { curve }),
        ]);
        const cusps = features.cusps.length ? (await api("eval", { curve, t: features.cusps })).points : [];
        return { c, points: flat.points, self, cusps };
      }),
    );
    this.draw(answers);
  },

  draw(answers) {
    const f = this.frame, svg = this.svg;
    redraw(svg);
    for (const a of answers) {
      const e = el("path", { class: "curve", id: "cr-curve-" + a.c.key, d: f.path(a.points), style: "stroke: " + a.c.color + "; stroke-width: 2" }, svg);
      e.dataset.points = JSON.stringify(a.points);
    }
    for (const a of answers) {
      const marks = el("g", { id: "cr-marks-" + a.c.key }, svg);
      marks.dataset.intersections = JSON.stringify(a.self.intersections.map((x) => x.point));
      marks.dataset.cusps = JSON.stringify(a.cusps);
      for (const x of a.self.intersections) el("circle", { cx: f.x(x.point), cy: f.y(x.point), r: 7, fill: "none", stroke: a.c.color, "stroke-width": 2.5 }, marks);
      for (const p of a.cusps) el("path", { d: "M" + (f.x(p) - 6) + " " + (f.y(p) - 6) + "l12 12m0 -12l-12 12", stroke: a.c.color, "stroke-width": 2.5 }, marks);
    }
    pointHandles(this, f, svg, 8);
    const dl = document.getElementById("cr-numbers");
    dl.replaceChildren();
    for (const a of answers) {
      const dt = Object.assign(document.createElement("dt"), { textContent: a.c.label });
      const n = a.self.intersections.length, m = a.cusps.length;
      const dd = Object.assign(document.createElement("dd"), { id: "cr-count-" + a.c.key, textContent: n + " self-intersection" + (n === 1 ? "" : "s") + ", " + m + " cusp" + (m === 1 ? "" : "s") });
      dl.append(dt, dd);
    }
  },
};

// ---------------------------------------------------------------------------------------
// View 7: SVG import (import_svg), with the pieces' control points, and export.

const SVG_EXAMPLE = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">\n' +
  '  <path id="heart" d="M 10,30 A 20,20 0,0,1 50,30 A 20,20 0,0,1 90,30 Q 90,60 50,90 Q 10,60 10,30 z"/>\n' +
  '  <rect id="box" x="105" y="20" width="36" height="24" rx="6"/>\n' +
  '  <path id="wave" d="M100 80 c10-12 20 12 30 0 s20 12 30 0"/>\n' +
  '</svg>';

function glyphDocument(answer) {
  const paths = answer.glyphs.filter((g) => g.curve).map((g) => ({ id: g.char, subpaths: g.curve.segments }));
  return { paths, skipped: answer.glyphs.filter((g) => !g.curve).map((g) => ({ element: "blank " + JSON.stringify(g.char) })) };
}

const importer = {
  doc: null,  // the import_svg response, its control points moved by drags
  tolerance: 0.01,

  init() {
    this.svg = document.getElementById("im-canvas");
    this.frame = new Frame(this.svg, 0, 100, 0, 100, 20, true, true);
    this.update = coalesced(() => this.compute());
    this.text = document.getElementById("im-text");
    this.text.value = SVG_EXAMPLE;
    this.pending = { svg: SVG_EXAMPLE };
    document.getElementById("im-import").addEventListener("click", () => this.load(this.text.value));
    document.getElementById("im-glyph").addEventListener("click", () => {
      this.pending = { glyph: { font: document.getElementById("im-font").value, text: document.getElementById("im-glyph-text").value, size: 100 } };
      this.doc = null;
      this.update();
    });
    // A file chosen, or dropped on the figure or the text (read as pending work, so that
    // explorerIdle waits for it).
    const readFile = async (file) => {
      if (!file) return;
      setPending(1);
      try {
        this.load((this.text.value = await file.text()));
      } finally {
        setPending(-1);
      }
    };
    document.getElementById("im-file").addEventListener("change", (e) => readFile(e.target.files[0]));
    for (const target of [this.svg, this.text]) {
      target.addEventListener("dragover", (e) => e.preventDefault());
      target.addEventListener("drop", (e) => {
        e.preventDefault();
        readFile(e.dataTransfer.files[0]);
      });
    }
    document.getElementById("im-export-svg").addEventListener("click", () => this.exportSvg());
    document.getElementById("im-export-json").addEventListener("click", () => this.exportJson());
  },

  // Reads an SVG document, or path data alone, through import_svg; fits the figure to it.
  load(text) {
    this.pending = text.trim().startsWith("<") ? { svg: text } : { d: text };
    this.doc = null;
    this.update();
  },

  subpaths() {
    const out = [];
    if (this.doc) this.doc.paths.forEach((p, i) => p.subpaths.forEach((s, j) => out.push({ shape: i, index: j, curve: s })));
    return out;
  },

  async compute() {
    if (this.pending) {
      const request = this.pending;
      this.pending = null;
      // A text's glyphs (y up) read as a document of one shape per glyph, each contour a
      // subpath; an SVG document (y down) as import_svg reads it.
      const doc = request.glyph ? glyphDocument(await api("glyph", request.glyph)) : await api("import_svg", request);
      this.frame.flip = !request.glyph;
      const subs = doc.paths.flatMap((p) => p.subpaths);
      const boxes = await Promise.all(subs.map((curve) => api("bounds", { curve })));
      if (boxes.length) {
        const lo = [Math.min(...boxes.map((b) => b.min[0])), Math.min(...boxes.map((b) => b.min[1]))];
        const hi = [Math.max(...boxes.map((b) => b.max[0])), Math.max(...boxes.map((b) => b.max[1]))];
        const size = Math.max(hi[0] - lo[0], hi[1] - lo[1]) || 1;
        this.frame.set(lo[0] - 0.05 * size, hi[0] + 0.05 * size, lo[1] - 0.05 * size, hi[1] + 0.05 * size);
        this.tolerance = size * 1e-3;
      }
      this.doc = doc;
    }
    const subs = this.subpaths();
    const answers = await Promise.all(
      subs.map(async (s) => {
        const [flat, length] = await Promise.all([api("flatten", { curve: s.curve, tolerance: this.tolerance }), api("length", { curve: s.curve })]);
        return { s, points: flat.points, length: length.length };
      }),
    );
    this.draw(answers);
  },

  draw(answers) {
    const f = this.frame, svg = this.svg;
    redraw(svg);
    svg.dataset.tolerance = String(this.tolerance);
    const counts = { line: 0, quadratic: 0, cubic: 0, arc: 0 };
    let total = 0;
    answers.forEach((a, k) => {
      const e = el("path", { class: "curve", id: "im-curve-" + k, d: f.path(a.points) }, svg);
      e.dataset.points = JSON.stringify(a.points);
      e.dataset.curve = JSON.stringify(a.s.curve);
      total += a.length;
      a.s.curve.segments.forEach((seg) => {
        if (seg.type === "rational_bezier") counts.arc++;
        else counts[["", "line", "quadratic", "cubic"][seg.points.length - 1]]++;
        if (seg.points.length > 2) el("path", { class: "polygon", d: f.path(seg.points) }, svg);
      });
    });
    answers.forEach((a, k) => {
      const segs = a.s.curve.segments;
      segs.forEach((seg, si) => {
        seg.points.forEach((p, pi) => {
          const end = pi === 0 || pi === seg.points.length - 1;
          const h = el("circle", { class: end ? "handle" : "handle inner", cx: f.x(p), cy: f.y(p), r: end ? 5 : 4, "data-subpath": k, "data-segment": si, "data-index": pi, "data-point": JSON.stringify(p) }, svg);
          h.onpointerdown = () => {
            // The points at the same place in this subpath (the joints) move together.
            this.dragged = [];
            segs.forEach((s2, sj) => s2.points.forEach((q, qi) => {
              if (q[0] === p[0] && q[1] === p[1]) this.dragged.push([sj, qi]);
            }));
          };
          dragHandle(f, h, pi, (_, w) => {
            for (const [sj, qi] of this.dragged || [[si, pi]]) segs[sj].points[qi] = w;
            this.update();
          });
        });
      });
    });
    const doc = this.doc;
    document.getElementById("im-shapes").textContent = doc ? doc.paths.map((p) => (p.id ? "#" + p.id : "(no id)") + ": " + p.subpaths.length + " subpath" + (p.subpaths.length === 1 ? "" : "s")).join(", ") : "";
    document.getElementById("im-pieces").textContent = counts.line + " lines, " + counts.quadratic + " quadratics, " + counts.cubic + " cubics, " + counts.arc + " arc pieces (rational quadratics)";
    document.getElementById("im-skipped").textContent = doc && doc.skipped.length ? doc.skipped.map((s) => s.element + (s.id ? "#" + s.id : "")).join(", ") : "none";
    document.getElementById("im-length").textContent = fmt(total);
  },

  // What is on screen, as SVG (to_svg_path for each subpath: exact for these pieces) or
  // JSON (the curves); the text is also kept on the page (#im-export).
  async exportSvg() {
    try {
      const ds = await Promise.all(this.subpaths().map((s) => api("to_svg_path", { curve: s.curve, tolerance: this.tolerance })));
      const body = ds.map((d) => '  <path d="' + d.d + '" fill="none" stroke="black"/>').join("\n");
      this.offer("curves.svg", "image/svg+xml", '<svg xmlns="http://www.w3.org/2000/svg">\n' + body + "\n</svg>\n");
    } catch (e) {
      status.textContent = e.message;
    }
  },

  exportJson() {
    this.offer("curves.json", "application/json", JSON.stringify({ curves: this.subpaths().map((s) => s.curve) }) + "\n");
  },

  offer(name, type, text) {
    const out = document.getElementById("im-export");
    out.textContent = text;
    const a = document.getElementById("im-download");
    if (a.href) URL.revokeObjectURL(a.href);
    a.href = URL.createObjectURL(new Blob([text], { type }));
    a.download = name;
    a.textContent = "download " + name;
    a.hidden = false;
  },
};

// ---------------------------------------------------------------------------------------
// View 8: affine maps (affine invariance).

const affine = {
  points: [[0.6, 1.0], [1.6, 4.6], [4.2, 0.6], [5.4, 4.2]],

  init() {
    this.svg = document.getElementById("af-canvas");
    this.frame = new Frame(this.svg, -0.5, 9.5, -0.5, 5.5);
    this.update = coalesced(() => this.compute());
    for (const id of ["af-angle", "af-sx", "af-sy", "af-shear"]) document.getElementById(id).addEventListener("input", () => this.update());
  },

  // The map A p = M p + b: a rotation of (scale x shear), about the origin, then moved right.
  map() {
    const v = (id) => Number(document.getElementById(id).value);
    const a = (v("af-angle") * Math.PI) / 180, c = Math.cos(a), s = Math.sin(a);
    const sx = v("af-sx"), sy = v("af-sy"), h = v("af-shear");
    // [c -s; s c] [sx h sy; 0 sy]
    const M = [[c * sx, c * h * sy - s * sy], [s * sx, s * h * sy + c * sy]];
    return { M, b: [5.6, 0.4] };
  },

  apply(A, p) {
    return [A.M[0][0] * p[0] + A.M[0][1] * p[1] + A.b[0], A.M[1][0] * p[0] + A.M[1][1] * p[1] + A.b[1]];
  },

  async compute() {
    const A = this.map();
    const mapped = this.points.map((p) => this.apply(A, p));
    const ts = linspace(0, 1, 161);
    const [orig, image] = await Promise.all([
      api("eval", { curve: { type: "bezier", points: this.points }, t: ts }),
      api("eval", { curve: { type: "bezier", points: mapped }, t: ts }),
    ]);
    this.draw({ A, mapped, orig, image, ts });
  },

  draw(r) {
    const f = this.frame, svg = this.svg;
    redraw(svg);
    el("path", { class: "polygon", d: f.path(this.points) }, svg);
    el("path", { class: "curve", id: "af-curve", d: f.path(r.orig.points), style: "stroke: #888" }, svg);
    el("path", { class: "polygon", d: f.path(r.mapped) }, svg);
    const image = el("path", { class: "curve", id: "af-image", d: f.path(r.image.points) }, svg);
    image.dataset.points = JSON.stringify(r.image.points);
    // The original's samples mapped by A, against the image curve at the same t.
    let err = 0;
    r.orig.points.forEach((p, i) => {
      const q = this.apply(r.A, p), c = r.image.points[i];
      err = Math.max(err, Math.hypot(q[0] - c[0], q[1] - c[1]));
      if (i % 8 === 0) el("circle", { class: "level-point", cx: f.x(q), cy: f.y(q), r: 3.5, fill: "#d35400" }, svg);
    });
    r.mapped.forEach((p, i) => el("rect", { class: "dependent", x: f.x(p) - 5, y: f.y(p) - 5, width: 10, height: 10, "data-mapped": i, "data-point": JSON.stringify(p) }, svg));
    pointHandles(this, f, svg, 8);
    const M = r.A.M;
    document.getElementById("af-matrix").textContent = "[[" + fmt(M[0][0]) + ", " + fmt(M[0][1]) + "], [" + fmt(M[1][0]) + ", " + fmt(M[1][1]) + "]] + " + fmtPoint(r.A.b);
    document.getElementById("af-error").textContent = err.toExponential(1);
    for (const id of ["af-angle", "af-sx", "af-sy", "af-shear"]) document.getElementById(id + "-out").textContent = document.getElementById(id).value;
  },
};

// ---------------------------------------------------------------------------------------
// View 9: degree reduction.

const reduce = {
  points: [[0.4, 0.8], [1.0, 4.6], [2.6, 5.0], [3.6, 1.2], [5.0, 0.4], [6.4, 3.4], [8.0, 5.0], [9.0, 1.4]],

  init() {
    this.svg = document.getElementById("rd-canvas");
    this.frame = new Frame(this.svg, -0.5, 9.5, -0.5, 5.5);
    this.update = coalesced(() => this.compute());
    const select = document.getElementById("rd-degree");
    for (let m = 1; m < this.points.length - 1; m++) select.appendChild(Object.assign(document.createElement("option"), { textContent: String(m), selected: m === 4 }));
    select.addEventListener("input", () => this.update());
  },

  async compute() {
    const curve = { type: "bezier", points: this.points };
    const n = this.points.length - 1, m = Number(document.getElementById("rd-degree").value);
    const ts = linspace(0, 1, 161);
    // A tolerance no curve on this figure reaches: the answer is always the reduction, with
    // its measured distance.
    const [samples, reduced] = await Promise.all([api("eval", { curve, t: ts }), api("reduce", { curve, times: n - m, tolerance: 1e6 })]);
    const low = await api("eval", { curve: reduced.curve, t: ts });
    this.draw({ samples, reduced, low, n, m });
  },

  draw(r) {
    const f = this.frame, svg = this.svg;
    redraw(svg);
    el("path", { class: "polygon", d: f.path(this.points) }, svg);
    const lowPoly = r.reduced.curve.points;
    const poly = el("path", { class: "elevated", id: "rd-polygon", d: f.path(lowPoly) }, svg);
    poly.dataset.points = JSON.stringify(lowPoly);
    for (const p of lowPoly) el("circle", { class: "elevated-point", cx: f.x(p), cy: f.y(p), r: 3.5 }, svg);
    const c = el("path", { class: "curve", id: "rd-curve", d: f.path(r.samples.points) }, svg);
    c.dataset.points = JSON.stringify(r.samples.points);
    const low = el("path", { class: "curve", id: "rd-reduced", d: f.path(r.low.points), style: "stroke: #e67e22" }, svg);
    low.dataset.points = JSON.stringify(r.low.points);
    pointHandles(this, f, svg, 8);
    document.getElementById("rd-from").textContent = r.n + " → " + r.m;
    document.getElementById("rd-error").textContent = fmt(r.reduced.max_error);
  },
};

// ---------------------------------------------------------------------------------------
// View 10: one form for every curve: a path's exact Bézier pieces.

const pieces = {
  // A polyline (own domain [0, 3]), a cubic, and a rational quarter circle (weights 1, √2/2, 1).
  segments: [
    { type: "polyline", points: [[0.4, 0.6], [1.8, 3.4], [3.0, 1.0], [4.0, 2.8]] },
    { type: "bezier", points: [[4.0, 2.8], [5.4, 5.2], [6.6, -0.4], [7.6, 1.2]] },
    { type: "rational_bezier", points: [[7.6, 1.2], [9.2, 1.2], [9.2, 2.8]], weights: [1, Math.SQRT1_2, 1] },
  ],

  init() {
    this.svg = document.getElementById("pc-canvas");
    this.frame = new Frame(this.svg, -0.5, 9.5, -0.5, 5.5);
    this.update = coalesced(() => this.compute());
    document.getElementById("pc-tol").addEventListener("input", () => this.update());
  },

  curve() {
    return { type: "path", segments: this.segments, breaks: [0, 1.5, 3, 4] };
  },

  tolerance() {
    return Math.pow(10, Number(document.getElementById("pc-tol").value));
  },

  async compute() {
    const curve = this.curve();
    const [bz, box, flat, length] = await Promise.all([
      api("to_bezier", { curve }),
      api("bounds", { curve }),
      api("flatten", { curve, tolerance: this.tolerance() }),
      api("length", { curve }),
    ]);
    const ts = linspace(0, 1, 41);
    const [samples, ends] = await Promise.all([
      Promise.all(bz.curve.segments.map((seg) => api("eval", { curve: seg, t: ts }))),
      api("eval", { curve, t: bz.curve.breaks }),
    ]);
    this.draw({ bz, box, flat, length, samples, ends });
  },

  draw(r) {
    const f = this.frame, svg = this.svg;
    redraw(svg);
    const [x0, y0] = r.box.min, [x1, y1] = r.box.max;
    const rect = el("rect", { class: "polygon", id: "pc-bounds", x: f.x([x0, 0]), y: f.y([0, y1]), width: f.x([x1, 0]) - f.x([x0, 0]), height: f.y([0, y0]) - f.y([0, y1]) }, svg);
    rect.dataset.box = JSON.stringify(r.box);
    r.bz.curve.segments.forEach((seg, i) => {
      el("path", { class: "polygon", d: f.path(seg.points) }, svg);
      const e = el("path", { class: "curve", "data-piece": i, d: f.path(r.samples[i].points), style: "stroke: " + (i % 2 ? "#e67e22" : "#1f5fbf") }, svg);
      e.dataset.points = JSON.stringify(r.samples[i].points);
    });
    const flat = el("path", { class: "level", id: "pc-flat-line", stroke: "#2a9d5c", d: f.path(r.flat.points) }, svg);
    flat.dataset.points = JSON.stringify(r.flat.points);
    for (const p of r.ends.points) el("circle", { class: "on-curve", cx: f.x(p), cy: f.y(p), r: 4 }, svg);
    this.segments.forEach((seg, si) => {
      seg.points.forEach((p, pi) => {
        const h = el("circle", { class: "handle", cx: f.x(p), cy: f.y(p), r: 7, "data-segment": si, "data-index": pi, "data-point": JSON.stringify(p) }, svg);
        h.onpointerdown = () => {
          // The points at the same place (the joints) move together.
          this.dragged = [];
          this.segments.forEach((s2, sj) => s2.points.forEach((q, qi) => {
            if (q[0] === p[0] && q[1] === p[1]) this.dragged.push([sj, qi]);
          }));
        };
        dragHandle(f, h, pi, (_, w) => {
          for (const [sj, qi] of this.dragged || [[si, pi]]) this.segments[sj].points[qi] = w;
          this.update();
        });
      });
    });
    const counts = {};
    for (const seg of r.bz.curve.segments) {
      const name = seg.type === "rational_bezier" ? "rational" : ["", "", "line", "quadratic", "cubic"][seg.points.length] || "degree " + (seg.points.length - 1);
      counts[name] = (counts[name] || 0) + 1;
    }
    document.getElementById("pc-count").textContent = r.bz.curve.segments.length + " (" + Object.entries(counts).map(([k, v]) => v + " " + k).join(", ") + ")";
    document.getElementById("pc-breaks").textContent = r.bz.curve.breaks.map(fmt).join(", ");
    document.getElementById("pc-box").textContent = fmtPoint(r.box.min) + " – " + fmtPoint(r.box.max);
    document.getElementById("pc-flat").textContent = r.flat.points.length + " vertices within " + this.tolerance().toExponential(2);
    document.getElementById("pc-length").textContent = fmt(r.length.length);
    document.getElementById("pc-tol-out").textContent = this.tolerance().toExponential(2);
  },
};

// ---------------------------------------------------------------------------------------
// View 11: fitting a B-spline to points.

const fitting = {
  // y = sin x + cos(3x) / 4 on [0, 2 pi], with a fixed "noise".
  points: [0.31, -0.12, 0.22, 0.05, -0.27, 0.18, -0.08, 0.14, -0.2, 0.09, 0.26, -0.16, 0.03, -0.1].map((e, i, a) => {
    const x = (2 * Math.PI * i) / (a.length - 1);
    return [0.5 + (8.5 * i) / (a.length - 1), 2.6 + 1.6 * (Math.sin(x) + Math.cos(3 * x) / 4) + 0.5 * e];
  }),

  init() {
    this.svg = document.getElementById("ft-canvas");
    this.frame = new Frame(this.svg, -0.5, 9.5, -0.5, 5.5);
    this.update = coalesced(() => this.compute());
    const count = document.getElementById("ft-count");
    count.max = String(this.points.length);
    for (const id of ["ft-degree", "ft-count"]) document.getElementById(id).addEventListener("input", () => this.update());
  },

  request() {
    const degree = Number(document.getElementById("ft-degree").value);
    const count = Math.max(degree + 1, Number(document.getElementById("ft-count").value));
    return { points: this.points, degree, control_points: count };
  },

  async compute() {
    const request = this.request();
    const fit = await api("fit", request);
    const samples = await api("eval", { curve: fit.curve, t: linspace(0, 1, 241) });
    this.draw({ request, fit, samples });
  },

  draw(r) {
    const f = this.frame, svg = this.svg;
    redraw(svg);
    const ctrl = r.fit.curve.points;
    const poly = el("path", { class: "elevated", id: "ft-polygon", d: f.path(ctrl) }, svg);
    poly.dataset.points = JSON.stringify(ctrl);
    for (const p of ctrl) el("circle", { class: "elevated-point", cx: f.x(p), cy: f.y(p), r: 3.5 }, svg);
    const c = el("path", { class: "curve", id: "ft-curve", d: f.path(r.samples.points) }, svg);
    c.dataset.points = JSON.stringify(r.samples.points);
    c.dataset.curve = JSON.stringify(r.fit.curve);
    pointHandles(this, f, svg, 6);
    const n = r.request.control_points;
    document.getElementById("ft-count-out").textContent = String(n);
    document.getElementById("ft-kind").textContent = (n === this.points.length ? "interpolation" : "least squares") + ", degree " + r.request.degree + ", " + n + " control points, " + this.points.length + " data points";
    document.getElementById("ft-error").textContent = fmt(r.fit.max_error);
  },
};

// ---------------------------------------------------------------------------------------
// 3-D views: an orthographic view from azimuth a and elevation e (degrees); world points
// on the screen as (p . right, p . up); a drag moves a point in the plane of the screen,
// or in a given plane (two axes).

class View3 {
  constructor(azimuth, elevation) {
    const a = (azimuth * Math.PI) / 180, e = (elevation * Math.PI) / 180;
    this.right = [-Math.sin(a), Math.cos(a), 0];
    this.up = [-Math.sin(e) * Math.cos(a), -Math.sin(e) * Math.sin(a), Math.cos(e)];
  }
  p(q) {
    const r = this.right, u = this.up;
    return [r[0] * q[0] + r[1] * q[1] + r[2] * q[2], u[0] * q[0] + u[1] * q[1] + u[2] * q[2]];
  }
  // q moved so that its projection lands on w: in the screen plane, or along axes i and j.
  moved(q, w, axes) {
    const s = this.p(q), dx = w[0] - s[0], dy = w[1] - s[1];
    if (!axes) return q.map((c, k) => c + dx * this.right[k] + dy * this.up[k]);
    const [i, j] = axes;
    const a = [this.right[i], this.up[i]], b = [this.right[j], this.up[j]];
    const det = a[0] * b[1] - a[1] * b[0];
    if (Math.abs(det) < 1e-6) return q;
    const out = q.slice();
    out[i] += (dx * b[1] - dy * b[0]) / det;
    out[j] += (a[0] * dy - a[1] * dx) / det;
    return out;
  }
}

// ---------------------------------------------------------------------------------------
// View 12: frames along a space curve.

const frames = {
  points: [[0, 0, 0], [3.2, 3.4, 1.2], [2.6, -3.0, 1.4], [6.0, 0, 2.4]],

  init() {
    this.svg = document.getElementById("fr-canvas");
    this.frame = new Frame(this.svg, -1.5, 7.5, -3.2, 3.2);
    this.update = coalesced(() => this.compute());
    for (const id of ["fr-frenet", "fr-rmf", "fr-az"]) document.getElementById(id).addEventListener("input", () => this.update());
  },

  view() {
    return new View3(Number(document.getElementById("fr-az").value), 55);
  },

  async compute() {
    const curve = { type: "bezier", points: this.points };
    const ts = linspace(0, 1, 241), at = linspace(0, 1, 25);
    const [samples, where, frenet, rmf] = await Promise.all([
      api("eval", { curve, t: ts }),
      api("eval", { curve, t: at }),
      api("frames", { curve, t: at, method: "frenet" }),
      api("frames", { curve, t: at, method: "rotation_minimizing" }),
    ]);
    this.draw({ samples, where, frenet, rmf });
  },

  // The normal's total twist about the tangent, in degrees: at each step the previous
  // normal is projected onto the plane normal to the new tangent, and the angle from it to
  // the new normal is added (null normals, where Frenet has none, skipped).
  twist(answer) {
    const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let sum = 0;
    for (let i = 1; i < answer.normals.length; i++) {
      const a = answer.normals[i - 1], b = answer.normals[i], t = answer.tangents[i];
      if (!a || !b) continue;
      const k = dot(a, t), p = [a[0] - k * t[0], a[1] - k * t[1], a[2] - k * t[2]];
      sum += Math.abs(Math.atan2(dot(cross(p, b), t), dot(p, b)));
    }
    return (sum * 180) / Math.PI;
  },

  // Fits the figure to the projected control points (on opening and when the view turns).
  fit(v) {
    const q = this.points.map((p) => v.p(p));
    const xs = q.map((p) => p[0]), ys = q.map((p) => p[1]);
    const lo = [Math.min(...xs), Math.min(...ys)], hi = [Math.max(...xs), Math.max(...ys)];
    const m = 0.15 * Math.max(hi[0] - lo[0], hi[1] - lo[1]) + 0.8;
    this.frame.set(lo[0] - m, hi[0] + m, lo[1] - m, hi[1] + m);
  },

  draw(r) {
    const svg = this.svg, v = this.view();
    const az = document.getElementById("fr-az").value;
    if (this.fitted !== az) {
      this.fit(v);
      this.fitted = az;
    }
    const f = this.frame;
    redraw(svg);
    el("path", { class: "polygon", d: f.path(this.points.map((q) => v.p(q))) }, svg);
    const c = el("path", { class: "curve", id: "fr-curve", d: f.path(r.samples.points.map((q) => v.p(q))) }, svg);
    c.dataset.points = JSON.stringify(r.samples.points);
    const L = 0.8;
    for (const [key, answer, color] of [["frenet", r.frenet, "#c0392b"], ["rmf", r.rmf, "#2a9d5c"]]) {
      const g = el("g", { id: "fr-normals-" + key }, svg);
      g.dataset.normals = JSON.stringify(answer.normals);
      if (!document.getElementById("fr-" + key).checked) continue;
      const d = answer.normals.map((n, i) => {
        if (!n) return "";
        const p = r.where.points[i], q = v.p(p), e = v.p(p.map((x, k) => x + L * n[k]));
        return "M" + f.x(q).toFixed(2) + " " + f.y(q).toFixed(2) + "L" + f.x(e).toFixed(2) + " " + f.y(e).toFixed(2);
      }).join("");
      el("path", { d, stroke: color, "stroke-width": 2, fill: "none" }, g);
    }
    this.points.forEach((p, i) => {
      const q = v.p(p);
      const h = el("circle", { class: "handle", cx: f.x(q), cy: f.y(q), r: 8, "data-index": i, "data-point": JSON.stringify(p) }, svg);
      dragHandle(f, h, i, (index, w) => {
        this.points[index] = this.view().moved(this.points[index], w);
        this.update();
      });
    });
    document.getElementById("fr-turn-frenet").textContent = this.twist(r.frenet).toFixed(1) + "°";
    document.getElementById("fr-turn-rmf").textContent = this.twist(r.rmf).toFixed(1) + "°";
    document.getElementById("fr-az-out").textContent = document.getElementById("fr-az").value;
  },
};

// ---------------------------------------------------------------------------------------
// View 13: surfaces (a patch's net, or the curves of a construction, dragged in 3-D).

const SURFACE_EXAMPLES = {
  // Rows of the 4 x 4 net of a bicubic Bézier patch.
  patch: [0, 1, 2, 3].map((i) => [0, 1, 2, 3].map((j) => [i, j, [[0, 0.4, 0.3, 0], [0.5, 1.6, 1.2, 0.4], [0.3, 1.0, 1.8, 0.6], [0, 0.2, 0.7, 0.2]][i][j]])),
  // A vase profile in the xz plane, turned about z.
  revolve: [[[1.0, 0, 0], [2.2, 0, 0.6], [0.4, 0, 1.8], [1.4, 0, 3.0]]],
  // Three cross-sections across y.
  loft: [0, 1.5, 3].map((y, k) => [[0, y, 0.6 * k], [1, y, 1.6 - 0.4 * k], [2, y, -0.3 + 0.5 * k], [3, y, 0.4]]),
  // c0, c1 (at v = 0, 1, running in u), d0, d1 (at u = 0, 1, running in v).
  coons: [
    [[0, 0, 0], [1, 0, 0.8], [2, 0, -0.4], [3, 0, 0]],
    [[0, 3, 0.5], [1.5, 3, 1.5], [3, 3, 0.5]],
    [[0, 0, 0], [0, 1.5, 1.2], [0, 3, 0.5]],
    [[3, 0, 0], [3, 1, -0.8], [3, 2, 0.8], [3, 3, 0.5]],
  ],
};

const surface = {
  data: JSON.parse(JSON.stringify(SURFACE_EXAMPLES)),

  init() {
    this.svg = document.getElementById("sf-canvas");
    this.frame = new Frame(this.svg, -3, 3, -2.2, 2.6);
    this.update = coalesced(() => this.compute());
    for (const id of ["sf-mode", "sf-az", "sf-el", "sf-mesh", "sf-tol"]) document.getElementById(id).addEventListener("input", () => this.update());
  },

  mode() {
    return document.getElementById("sf-mode").value;
  },

  view() {
    return new View3(Number(document.getElementById("sf-az").value), Number(document.getElementById("sf-el").value));
  },

  // The model's centre, subtracted before projecting (the views turn about it).
  centre() {
    return { patch: [1.5, 1.5, 0.6], revolve: [0, 0, 1.5], loft: [1.5, 1.5, 0.5], coons: [1.5, 1.5, 0.3] }[this.mode()];
  },

  // The surface object: the patch's net itself, or the construction's answer.
  async build() {
    const mode = this.mode(), d = this.data[mode];
    const bez = (points) => ({ type: "bezier", points });
    if (mode === "patch") return { type: "bezier_surface", points: d };
    const request = mode === "revolve"
      ? { construct: "revolve", curve: bez(d[0]), axis: { point: [0, 0, 0], direction: [0, 0, 1] } }
      : { construct: mode, curves: d.map(bez) };
    return (await api("surface", request)).surface;
  },

  domain(s) {
    if (!s.knots) return [[0, 1], [0, 1]];
    const rows = s.points.length, cols = s.points[0].length, [p, q] = s.degree, [U, V] = s.knots;
    return [[U[p], U[rows]], [V[q], V[cols]]];
  },

  async compute() {
    const s = await this.build();
    const [[u0, u1], [v0, v1]] = this.domain(s);
    const lines = 9, steps = 40, uv = [];
    for (let k = 0; k < lines; k++) {
      const a = k / (lines - 1);
      for (let j = 0; j <= steps; j++) uv.push([u0 + a * (u1 - u0), v0 + (j / steps) * (v1 - v0)]);
      for (let j = 0; j <= steps; j++) uv.push([u0 + (j / steps) * (u1 - u0), v0 + a * (v1 - v0)]);
    }
    const mesh = document.getElementById("sf-mesh").checked;
    const tolerance = Math.pow(10, Number(document.getElementById("sf-tol").value));
    const [grid, area, tess] = await Promise.all([
      api("eval", { surface: s, uv }),
      api("area", { surface: s }),
      mesh ? api("tessellate", { surface: s, tolerance }) : null,
    ]);
    this.draw({ s, uv, grid, area, tess, lines, steps, tolerance });
  },

  draw(r) {
    const f = this.frame, svg = this.svg, v = this.view(), c = this.centre();
    const P = (q) => v.p([q[0] - c[0], q[1] - c[1], q[2] - c[2]]);
    redraw(svg);
    if (r.tess) {
      const V = r.tess.vertices.map(P);
      const d = r.tess.triangles.map(([a, b, k]) => "M" + [a, b, k, a].map((i) => f.x(V[i]).toFixed(1) + " " + f.y(V[i]).toFixed(1)).join("L")).join("");
      el("path", { d, stroke: "#9ab", "stroke-width": 0.6, fill: "none", id: "sf-mesh-lines" }, svg);
    }
    const n = r.steps + 1, pts = r.grid.points;
    const iso = el("g", { id: "sf-isocurves" }, svg);
    iso.dataset.points = JSON.stringify(pts);
    iso.dataset.uv = JSON.stringify(r.uv);
    for (let k = 0; k < 2 * r.lines; k++) el("path", { class: "curve", d: f.path(pts.slice(k * n, (k + 1) * n).map(P)), style: "stroke-width: 1.6; stroke: " + (k % 2 ? "#1f5fbf" : "#e67e22") }, iso);
    const mode = this.mode(), d = this.data[mode];
    // The net (patch) or the curves' polygons, and their points to drag.
    if (mode === "patch") {
      for (let i = 0; i < 4; i++) {
        el("path", { class: "polygon", d: f.path(d[i].map(P)) }, svg);
        el("path", { class: "polygon", d: f.path(d.map((row) => row[i]).map(P)) }, svg);
      }
    } else {
      for (const curve of d) el("path", { class: "polygon", d: f.path(curve.map(P)) }, svg);
    }
    d.forEach((curve, ci) => curve.forEach((p, pi) => {
      const q = P(p);
      const h = el("circle", { class: "handle", cx: f.x(q), cy: f.y(q), r: 6, "data-curve": ci, "data-index": pi, "data-point": JSON.stringify(p) }, svg);
      h.onpointerdown = () => {
        // Points at the same place (the Coons corners) move together.
        this.dragged = [];
        d.forEach((c2, cj) => c2.forEach((q2, qj) => {
          if (q2.every((x, k) => x === p[k])) this.dragged.push([cj, qj]);
        }));
      };
      dragHandle(f, h, pi, (_, w) => {
        const cur = d[ci][pi], moved = this.view().moved([cur[0] - c[0], cur[1] - c[1], cur[2] - c[2]], w, mode === "revolve" ? [0, 2] : null);
        const to = [moved[0] + c[0], moved[1] + c[1], moved[2] + c[2]];
        for (const [cj, qj] of this.dragged || [[ci, pi]]) d[cj][qj] = to.slice();
        this.update();
      });
    }));
    const s = r.s;
    document.getElementById("sf-type").textContent = s.type + ", degree " + (s.degree || [s.points.length - 1, s.points[0].length - 1]).join(" × ") + ", " + s.points.length + " × " + s.points[0].length + " control points";
    document.getElementById("sf-area").textContent = fmt(r.area.area);
    document.getElementById("sf-triangles").textContent = r.tess ? r.tess.triangles.length + " within " + r.tolerance.toExponential(2) : "—";
    document.getElementById("sf-az-out").textContent = document.getElementById("sf-az").value;
    document.getElementById("sf-el-out").textContent = document.getElementById("sf-el").value;
    document.getElementById("sf-tol-out").textContent = r.tolerance.toExponential(2);
  },
};

// ---------------------------------------------------------------------------------------
// Views and navigation (#bezier, #composite, #bspline, #interpolation, #hermite, #catmull,
// #subdivision, #queries, #import, #affine, #reduce, #pieces, #fit, #frames, #surface).

const views = { bezier, composite, bspline, interpolation, hermite, catmull, subdivision, queries, import: importer, affine, reduce, pieces, fit: fitting, frames, surface };

function show() {
  const name = (location.hash || "#bezier").slice(1);
  const current = views[name] ? name : "bezier";
  for (const key of Object.keys(views)) document.getElementById("view-" + key).hidden = key !== current;
  for (const a of document.querySelectorAll("nav a")) a.classList.toggle("active", a.dataset.view === current);
  views[current].update();
}

for (const v of Object.values(views)) v.init();
window.addEventListener("hashchange", show);
show();
