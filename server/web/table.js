// The table in SVG, to scale, in the table frame's metres: one group flips y so that every
// coordinate written into the page (ball centres, path vertices) is the engine's number as it
// came, unrounded. Balls are dragged; a drag from the cloth sets the aim; clicks pick balls,
// pockets and targets for the planner.

const NS = "http://www.w3.org/2000/svg";

export const COLOURS = {
  cue: "#f7f4ea",
  red: "#c8102e",
  yellow: "#f2d022",
  green: "#138a36",
  brown: "#7b4a1e",
  blue: "#1d4fbf",
  pink: "#f08bb4",
  black: "#111111",
};

// The colour of a ball: its kind, else its id (ids such as red7 name their kind).
export function ballColour(id, kind) {
  if (kind && COLOURS[kind]) return COLOURS[kind];
  if (COLOURS[id]) return COLOURS[id];
  if (/^red/.test(id)) return COLOURS.red;
  return "#bbbbbb";
}

function el(name, attrs = {}, parent = null) {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

export class Table {
  constructor(svg) {
    this.svg = svg;
    this.handlers = {};
    this.view = null;
    this.balls = [];
    this.frame = null;
    this.pointer = null;
    this.locked = false;
    svg.addEventListener("pointerdown", (e) => this.down(e));
    svg.addEventListener("pointermove", (e) => this.move(e));
    svg.addEventListener("pointerup", (e) => this.up(e));
    svg.addEventListener("pointercancel", (e) => this.up(e));
  }

  on(name, f) {
    this.handlers[name] = f;
  }

  emit(name, ...args) {
    if (this.handlers[name]) this.handlers[name](...args);
  }

  // The extent drawn: the table with its cushions, or on the open table the balls with room.
  extent(balls) {
    const v = this.view;
    if (v.kind === "snooker" || v.length > 0) {
      const m = 0.12;
      return [-m, -m, v.length + m, v.width + m];
    }
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    for (const b of balls) {
      x0 = Math.min(x0, b.pos[0]);
      y0 = Math.min(y0, b.pos[1]);
      x1 = Math.max(x1, b.pos[0]);
      y1 = Math.max(y1, b.pos[1]);
    }
    if (!isFinite(x0)) [x0, y0, x1, y1] = [0, 0, 1, 0.5];
    const m = 0.4;
    return [x0 - m, y0 - m, x1 + m, y1 + m];
  }

  // Draws the table `view` (the server's TableView) with `balls` (the scene's balls).
  setTable(view, balls) {
    this.view = view;
    const svg = this.svg;
    svg.replaceChildren();
    const [x0, y0, x1, y1] = this.extent(balls);
    this.bounds = [x0, y0, x1, y1];
    svg.setAttribute("viewBox", `${x0} ${-y1} ${x1 - x0} ${y1 - y0}`);
    // y up: the table frame.
    const g = el("g", { transform: "scale(1,-1)", id: "frame" }, svg);
    this.g = g;
    const R = view.ball_radius;
    el("rect", { x: x0, y: y0, width: x1 - x0, height: y1 - y0, class: "rail" }, g);
    if (view.kind === "snooker") {
      el("rect", { x: 0, y: 0, width: view.length, height: view.width, class: "cloth" }, g);
      for (const p of view.pockets) {
        el("circle", { cx: p.centre[0], cy: p.centre[1], r: p.radius, class: "pocket", "data-pocket": p.name }, g);
      }
      for (const c of view.cushions) {
        el("line", { x1: c.start[0], y1: c.start[1], x2: c.end[0], y2: c.end[1], class: "cushion" }, g);
      }
      for (const j of view.jaws) {
        el("circle", { cx: j.centre[0], cy: j.centre[1], r: j.radius, class: "jaw" }, g);
      }
      if (view.baulk_line != null) {
        el("line", { x1: view.baulk_line, y1: 0, x2: view.baulk_line, y2: view.width, class: "marking" }, g);
      }
      const brown = view.spots.find((s) => s.name === "brown");
      if (brown && view.d_radius) {
        const r = view.d_radius;
        const [bx, by] = brown.pos;
        el("path", { d: `M ${bx} ${by - r} A ${r} ${r} 0 0 0 ${bx} ${by + r}`, class: "marking" }, g);
      }
      for (const s of view.spots) {
        el("circle", { cx: s.pos[0], cy: s.pos[1], r: R * 0.18, class: "spot" }, g);
      }
    } else {
      el("rect", { x: x0, y: y0, width: x1 - x0, height: y1 - y0, class: "cloth" }, g);
    }
    this.layers = {
      marks: el("g", { id: "marks" }, g),
      alternatives: el("g", { id: "alt-paths" }, g),
      paths: el("g", { id: "paths" }, g),
      aim: el("g", { id: "aim-layer" }, g),
      balls: el("g", { id: "balls" }, g),
    };
    this.setBalls(balls);
  }

  // Draws `balls` (the scene's [[balls]]) where they lie.
  setBalls(balls) {
    this.balls = balls;
    const layer = this.layers.balls;
    layer.replaceChildren();
    const R = this.view.ball_radius;
    for (const b of balls) {
      const c = el("circle", {
        cx: b.pos[0],
        cy: b.pos[1],
        r: R,
        fill: ballColour(b.id, b.kind),
        class: "ball",
        "data-ball": b.id,
      }, layer);
      c.appendChild(el("title")).textContent = b.id;
    }
  }

  ballNode(id) {
    return this.layers.balls.querySelector(`[data-ball="${CSS.escape(id)}"]`);
  }

  // Moves a ball's drawing (animation; the scene is not changed).
  place(id, x, y, visible = true) {
    const n = this.ballNode(id);
    if (!n) return;
    n.setAttribute("cx", x);
    n.setAttribute("cy", y);
    n.style.visibility = visible ? "visible" : "hidden";
  }

  // Table-frame point of a pointer event.
  point(e) {
    const m = this.g.getScreenCTM().inverse();
    const p = new DOMPoint(e.clientX, e.clientY).matrixTransform(m);
    return [p.x, p.y];
  }

  ballAt([x, y]) {
    const R = this.view.ball_radius;
    let best = null;
    let bestD = 1.6 * R;
    for (const b of this.balls) {
      const d = Math.hypot(b.pos[0] - x, b.pos[1] - y);
      if (d < bestD) {
        best = b;
        bestD = d;
      }
    }
    return best;
  }

  pocketAt([x, y]) {
    if (!this.view.pockets) return null;
    for (const p of this.view.pockets) {
      if (Math.hypot(p.centre[0] - x, p.centre[1] - y) < p.radius + 0.05) return p;
    }
    return null;
  }

  down(e) {
    // Locked while the page is busy: the position must stay the one asked of.
    if (!this.view || e.button !== 0 || this.locked) return;
    this.emit("touch");
    const at = this.point(e);
    const ball = this.ballAt(at);
    this.pointer = { start: at, ball, moved: false, id: e.pointerId };
    this.svg.setPointerCapture(e.pointerId);
    e.preventDefault();
  }

  move(e) {
    const p = this.pointer;
    if (!p || p.id !== e.pointerId) return;
    const at = this.point(e);
    const R = this.view.ball_radius;
    if (!p.moved && Math.hypot(at[0] - p.start[0], at[1] - p.start[1]) < 0.25 * R) return;
    p.moved = true;
    if (p.ball) {
      this.place(p.ball.id, at[0], at[1]);
      this.emit("dragging", p.ball.id, at);
    } else {
      this.emit("aiming", at);
    }
  }

  up(e) {
    const p = this.pointer;
    if (!p || p.id !== e.pointerId) return;
    this.pointer = null;
    const at = this.point(e);
    if (!p.moved) {
      this.emit("click", { at, ball: p.ball, pocket: this.pocketAt(at) });
    } else if (p.ball) {
      this.emit("dropped", p.ball.id, at);
    } else {
      this.emit("aimed", at);
    }
  }

  clear(layer) {
    this.layers[layer].replaceChildren();
  }

  // Draws each ball's sampled path (the server's Paths) as a polyline in `layer`.
  drawPaths(paths, layer = "paths", cls = "path") {
    const g = this.layers[layer];
    for (const b of paths.balls ? paths.balls : paths) {
      if (b.t.length < 2) continue;
      const moved = b.x.some((x, i) => x !== b.x[0] || b.y[i] !== b.y[0]);
      if (!moved) continue;
      const pts = b.x.map((x, i) => `${x},${b.y[i]}`).join(" ");
      el("polyline", {
        points: pts,
        class: cls,
        stroke: ballColour(b.id, b.kind),
        "data-ball": b.id,
      }, g);
    }
  }

  // The cue line of a strike: from the struck ball along `aim`, `length` m.
  drawAim(ball, aim, length) {
    const g = this.layers.aim;
    g.replaceChildren();
    if (!ball) return;
    const [x, y] = ball.pos;
    const R = this.view.ball_radius;
    const bx = x - Math.cos(aim) * (R * 1.6);
    const by = y - Math.sin(aim) * (R * 1.6);
    el("line", { x1: bx, y1: by, x2: bx - Math.cos(aim) * 0.9, y2: by - Math.sin(aim) * 0.9, class: "cue-stick" }, g);
    el("line", { x1: x, y1: y, x2: x + Math.cos(aim) * length, y2: y + Math.sin(aim) * length, class: "aim-line" }, g);
  }

  mark(kind, attrs) {
    const g = this.layers.marks;
    return el(kind, attrs, g);
  }
}

// Animates `paths` in real time (times `speed`), calling `onTick(t)`; returns a stop function.
export function animate(table, paths, onTick, speed = 1) {
  const balls = paths.balls;
  const idx = balls.map(() => 0);
  let t0 = null;
  let stopped = false;
  function at(b, k, t) {
    // The sample interval that holds t; linear between samples (every event is a sample).
    while (k + 1 < b.t.length && b.t[k + 1] <= t) k++;
    if (k + 1 >= b.t.length) return [k, b.x[k], b.y[k]];
    const a = (t - b.t[k]) / (b.t[k + 1] - b.t[k]);
    return [k, b.x[k] + a * (b.x[k + 1] - b.x[k]), b.y[k] + a * (b.y[k + 1] - b.y[k])];
  }
  function frame(now) {
    if (stopped) return;
    if (t0 === null) t0 = now;
    const t = Math.min(((now - t0) / 1000) * speed, paths.duration);
    balls.forEach((b, i) => {
      const [k, x, y] = at(b, idx[i], t);
      idx[i] = k;
      const gone = b.gone_at != null && t >= b.gone_at;
      table.place(b.id, x, y, !gone);
    });
    onTick(t, t >= paths.duration);
    if (t < paths.duration) requestAnimationFrame(frame);
  }
  requestAnimationFrame(frame);
  return () => {
    stopped = true;
  };
}
