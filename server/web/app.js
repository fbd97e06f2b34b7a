// The shot lab's page: one position (a scene, or a frame of snooker) drawn on the table, a
// strike set by hand, and the three panels that ask the server for shots, plans and verdicts.
// Every number shown comes from the server (the engine, scene, planner and rules crates).

import * as api from "./api.js";
import { Table, animate } from "./table.js";
import { StrikeControls } from "./strike.js";
import { PlanPanel } from "./plan.js";
import { PlayPanel } from "./play.js";
import { PlayerPanel } from "./player.js";

const $ = (id) => document.getElementById(id);

class Lab {
  constructor() {
    this.info = null;
    this.position = null;
    this.shot = null;
    this.stop = null;
    this.busy = false;
    this.table = new Table($("table"));
    this.strikes = new StrikeControls(this);
    this.plan = new PlanPanel(this);
    this.play = new PlayPanel(this);
    this.player = new PlayerPanel(this);
    this.animating = false;
    // The frame of the position has ended (a stroke's verdict said so): no more strokes.
    this.frameOver = false;
    // Called when the running animation ends (a stroke's bookkeeping); see stopAnimation.
    this.after = null;
    // The shot shown is a stroke already applied: the position is the frame it left.
    this.shotKept = false;
  }

  // While a stroke, a visit or a plan runs the page is busy: nothing that changes the
  // position or starts other work is offered (the table takes no drags), so what arrives is
  // always drawn on the position it was asked of.
  lock(on) {
    this.busy = on;
    this.table.locked = on;
    this.refreshControls();
  }

  // Every button's state from the page's.
  refreshControls() {
    const busy = this.busy;
    const frame = this.position && this.position.frame;
    const set = (id, disabled) => {
      $(id).disabled = disabled;
    };
    for (const id of ["strike", "load-layout", "new-frame", "upload", "import", "pick", "plan", "paste"]) set(id, busy);
    set("replay", busy || !this.shot);
    set("play-stroke", busy || !frame || this.frameOver);
    set("player-visit", busy || !frame || this.frameOver || !(this.info && this.info.player));
    set("play-plan", busy || !this.plan.result);
    set("plan-cancel", !this.plan.running);
    set("player-cancel", !this.player.running);
  }

  status(text, error = false) {
    const s = $("status");
    s.textContent = text;
    s.className = error ? "error" : "";
  }

  // Reports a failed request: the server's message names the key at fault.
  fail(e) {
    this.status(e instanceof api.ApiError ? e.message : `error: ${e.message}`, true);
  }

  get strike() {
    return this.strikes.strike;
  }

  ball(id) {
    return this.position.scene.balls.find((b) => b.id === id);
  }

  // The scene of a request: the position with the strike as its `cue`.
  scene() {
    const s = structuredClone(this.position.scene);
    s.cue = structuredClone(this.strike);
    return s;
  }

  // Shows `position` (the server's Position): the table, the balls, the panels' choices.
  setPosition(position, about = "") {
    this.stopAnimation();
    const scene = position.scene;
    scene.balls = scene.balls || [];
    // A cue ball in hand goes where the rules put it until dragged.
    if (position.frame && position.frame.ball_in_hand && !scene.balls.some((b) => b.id === "cue")) {
      const at = position.rules && position.rules.in_hand_place;
      if (at) scene.balls.unshift({ id: "cue", pos: [at[0], at[1]] });
    }
    // The scene's own strike, if it has one, is the strike offered.
    const own = scene.cue;
    delete scene.cue;
    this.position = position;
    this.shot = null;
    this.shotKept = false;
    this.frameOver = false;
    this.table.setTable(position.table, scene.balls);
    this.strikes.setBalls(scene.balls.map((b) => b.id));
    if (own && own.ball) {
      this.strikes.set({ offset: [0, 0], elevation: 0, ...own });
    }
    this.strikes.show();
    this.plan.setPosition(position);
    this.play.setPosition(position);
    this.player.setPosition(position);
    $("position-about").textContent = about;
    $("events").replaceChildren();
    $("summary").textContent = "";
    this.refreshControls();
    this.redrawAim();
  }

  // After a stroke's next position is set: its shot stays shown (paths, events) and can be
  // replayed from the frame it was played from.
  keepShot(view) {
    this.shot = view;
    this.shotKept = true;
    this.table.drawPaths(view.paths);
    this.listEvents(view.result);
    this.refreshControls();
  }

  redrawAim() {
    if (!this.position || this.animating) return;
    this.table.drawAim(this.ball(this.strike.ball), this.strike.aim, 0.6);
  }

  // Stops the animation; a stroke's bookkeeping waiting for its end is done now, so that
  // nothing waits for an end that will not come.
  stopAnimation() {
    if (this.stop) this.stop();
    this.stop = null;
    this.animating = false;
    document.body.dataset.animating = "false";
    const after = this.after;
    this.after = null;
    if (after) after();
  }

  // Puts the balls back where the position has them.
  restBalls() {
    this.table.setBalls(this.position.scene.balls);
  }

  // Draws `view` (the server's ShotView): paths, events, and the balls animated in real time.
  showShot(view, after = null) {
    this.stopAnimation();
    this.shot = view;
    this.table.clear("paths");
    this.table.clear("aim");
    this.table.drawPaths(view.paths);
    this.listEvents(view.result);
    this.shotKept = false;
    this.refreshControls();
    this.run(view, after);
  }

  run(view, after) {
    this.stopAnimation();
    // The balls drawn where the shot starts: the position's, or for a stroke kept the frame
    // it was played from (the drawings only: the table takes the position's back when touched).
    this.table.setBalls(view.paths.balls.map((b) => ({ id: b.id, kind: b.kind, pos: [b.x[0], b.y[0]] })));
    const replayOfKept = this.shotKept;
    this.animating = true;
    this.after = after;
    const speed = Number($("replay-speed").value);
    document.body.dataset.animating = "true";
    this.stop = animate(this.table, view.paths, (t, done) => {
      $("clock").textContent = `t = ${t.toFixed(3)} s`;
      if (done) {
        this.stop = null;
        this.stopAnimation();
        // A stroke replayed ends on the frame it left (the colours respotted).
        if (replayOfKept) this.restBalls();
      }
    }, speed);
  }

  listEvents(result) {
    const list = $("events");
    list.replaceChildren(
      ...result.events.map((e) => {
        const li = document.createElement("li");
        const where = e.cushion ? ` ${e.cushion}` : e.pocket ? ` ${e.pocket}` : "";
        li.textContent = `${e.t.toFixed(4)} s  ${e.kind}  ${e.balls.join("–")}${where}`;
        return li;
      }),
    );
    const potted = Object.entries(result.final)
      .filter(([, s]) => s.motion === "pocketed" || s.motion === "off_table")
      .map(([id, s]) => `${id} (${s.motion.replace("_", " ")})`);
    const last = result.events.length ? result.events[result.events.length - 1].t : 0;
    $("summary").textContent =
      `${result.events.length} events over ${last.toFixed(3)} s` +
      (potted.length ? `; ${potted.join(", ")}` : "; nothing potted");
  }

  async strikeNow() {
    if (this.busy) return;
    this.lock(true);
    try {
      this.status("simulating…");
      const view = await api.post("/api/simulate", { scene: this.scene() });
      this.showShot(view);
      this.status(`simulated: ${view.result.events.length} events`);
    } catch (e) {
      this.fail(e);
    } finally {
      this.lock(false);
    }
  }

  async loadLayout(name) {
    try {
      const q = name === "open-table" ? `?reds=${Number($("reds").value)}&seed=${Number($("seed").value)}` : "";
      const p = await api.get(`/api/layouts/${encodeURIComponent(name)}${q}`);
      const about = (this.info.layouts.find((l) => l.name === name) || {}).about || "";
      this.setPosition(p, about);
      this.status(`layout ${name}`);
    } catch (e) {
      this.fail(e);
    }
  }

  // A scene file, a frame file, or a play log line (its `frame`), as text.
  async importText(text, name) {
    let toml = text;
    const trimmed = text.trim();
    if (trimmed.startsWith("{")) {
      try {
        const line = JSON.parse(trimmed.split("\n")[0]);
        if (typeof line.frame === "string") toml = line.frame;
      } catch {
        // Not JSON after all: read as TOML, whose parser names the fault.
      }
    }
    try {
      const p = await api.post("/api/scene/import", { toml, name });
      this.setPosition(p, `from ${name}`);
      this.status(`read ${name}`);
    } catch (e) {
      this.fail(e);
    }
  }

  async download(kind) {
    try {
      const f = await api.download(`/api/download/${kind}`, { scene: this.scene() });
      this.status(`downloaded ${f.name} (${f.size} bytes)`);
    } catch (e) {
      this.fail(e);
    }
  }

  wire() {
    const t = this.table;
    // A touch puts the balls back where the position has them (after a shot they are drawn
    // where it left them), so that what is grabbed is the position's ball.
    t.on("touch", () => {
      if (this.animating) this.stopAnimation();
      this.restBalls();
    });
    t.on("dragging", () => this.table.clear("aim"));
    t.on("dropped", (id, at) => {
      const b = this.ball(id);
      b.pos = [at[0], at[1]];
      this.table.clear("paths");
      // A plan was of the position before the move: it no longer holds.
      this.plan.clearResult();
      this.redrawAim();
      this.status(`${id} moved to (${at[0].toFixed(4)}, ${at[1].toFixed(4)})`);
    });
    t.on("aiming", (at) => {
      const b = this.ball(this.strike.ball);
      if (b) this.strikes.setAim(Math.atan2(at[1] - b.pos[1], at[0] - b.pos[0]));
    });
    t.on("aimed", () => this.redrawAim());
    t.on("click", (c) => this.plan.pick(c));
    $("strike").addEventListener("click", () => this.strikeNow());
    $("replay").addEventListener("click", () => !this.busy && this.shot && this.run(this.shot, null));
    $("load-layout").addEventListener("click", () => this.loadLayout($("layout").value));
    $("layout").addEventListener("change", () => {
      $("open-table-opts").hidden = $("layout").value !== "open-table";
    });
    $("upload").addEventListener("change", async () => {
      const f = $("upload").files[0];
      if (f) await this.importText(await f.text(), f.name);
    });
    $("import").addEventListener("click", () => this.importText($("paste").value, "pasted.toml"));
    $("dl-scene").addEventListener("click", () => this.download("scene"));
    $("dl-result").addEventListener("click", () => this.download("result"));
    $("dl-recording").addEventListener("click", () => this.download("recording"));
    this.plan.wire();
    this.play.wire();
    this.player.wire();
  }

  async start() {
    this.wire();
    this.info = await api.get("/api/info");
    $("version").textContent = `v${this.info.version}`;
    $("dl-recording").disabled = !this.info.recordings;
    const sel = $("layout");
    sel.replaceChildren(
      ...this.info.layouts.map((l) => {
        const o = document.createElement("option");
        o.value = l.name;
        o.textContent = `${l.name} (${l.kind})`;
        o.title = l.about;
        return o;
      }),
    );
    sel.value = "cut-30";
    $("open-table-opts").hidden = true;
    this.player.setInfo(this.info);
    await this.loadLayout("cut-30");
    document.body.dataset.ready = "true";
  }
}

const lab = new Lab();
// For the browser tests and the curious: the page's state, read-only by convention.
window.lab = lab;
lab.start().catch((e) => lab.fail(e));
