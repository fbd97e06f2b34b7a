// The Plan panel: a ball, a pocket and a target for the cue ball picked on the table; the
// planner (thesis chapter 7) run as a job on the server with its progress shown and a cancel
// button; its best shot and alternatives drawn, with the pot probability under execution noise
// and the spread of the cue ball's end (a circle of that radius about the noisy runs' mean).

import * as api from "./api.js";

const $ = (id) => document.getElementById(id);
const DEG = Math.PI / 180;

export class PlanPanel {
  constructor(lab) {
    this.lab = lab;
    this.picking = null;
    this.job = null;
    // From the click to the plan's end (the job's id comes later).
    this.running = false;
    this.cancelRequested = false;
    this.result = null;
  }

  setPosition(position) {
    const balls = position.scene.balls.map((b) => b.id).filter((id) => id !== "cue");
    const pots = $("plan-pot");
    const keep = pots.value;
    pots.replaceChildren(...balls.map((id) => new Option(id, id)));
    if (balls.includes(keep)) pots.value = keep;
    const pockets = (position.table.pockets || []).map((p) => p.name);
    const pk = $("plan-pocket");
    const keepPk = pk.value;
    pk.replaceChildren(...pockets.map((n) => new Option(n, n)));
    if (pockets.includes(keepPk)) pk.value = keepPk;
    // A new position starts a new choice: nothing picked, no target, no plan.
    this.picked = false;
    $("target-x").value = "";
    $("target-y").value = "";
    this.clearResult();
  }

  // Forgets the plan shown (its position changed): its table, its paths, its spread.
  clearResult() {
    this.result = null;
    $("plan-status").textContent = "";
    $("plan-result").replaceChildren();
    if (this.lab.table.layers) this.lab.table.clear("alternatives");
    this.drawChoice();
    this.lab.refreshControls();
  }

  target() {
    const x = Number($("target-x").value);
    const y = Number($("target-y").value);
    return $("target-x").value !== "" && $("target-y").value !== "" ? [x, y] : null;
  }

  // Marks the ball, pocket and target chosen.
  drawChoice() {
    const t = this.lab.table;
    if (!t.layers) return;
    t.clear("marks");
    const R = t.view.ball_radius;
    const b = this.lab.position.scene.balls.find((b) => b.id === $("plan-pot").value);
    if (b && this.picked) t.mark("circle", { cx: b.pos[0], cy: b.pos[1], r: 1.6 * R, class: "picked" });
    const pk = (t.view.pockets || []).find((p) => p.name === $("plan-pocket").value);
    if (pk && this.picked) t.mark("circle", { cx: pk.centre[0], cy: pk.centre[1], r: pk.radius + 0.01, class: "picked" });
    const tg = this.target();
    if (tg) {
      t.mark("circle", { cx: tg[0], cy: tg[1], r: R, class: "target", id: "target-mark" });
      t.mark("line", { x1: tg[0] - R, y1: tg[1], x2: tg[0] + R, y2: tg[1], class: "target" });
      t.mark("line", { x1: tg[0], y1: tg[1] - R, x2: tg[0], y2: tg[1] + R, class: "target" });
    }
    if (this.result) {
      const r = this.result.plan.best.robustness;
      if (r) {
        t.mark("circle", { cx: r.cue_final_mean[0], cy: r.cue_final_mean[1], r: Math.max(r.cue_final_spread, 1e-4), class: "spread", id: "spread" });
        t.mark("circle", { cx: r.cue_final_mean[0], cy: r.cue_final_mean[1], r: 0.15 * R, class: "mean" });
      }
    }
  }

  // A click on the table while picking: the ball to pot, then the pocket, then the target.
  pick(c) {
    if (!this.picking) return;
    if (this.picking === "ball") {
      if (!c.ball || c.ball.id === this.lab.strike.ball) return this.lab.status("click the ball to pot");
      $("plan-pot").value = c.ball.id;
      this.picking = "pocket";
      this.lab.status(`pot ${c.ball.id}: now click a pocket`);
    } else if (this.picking === "pocket") {
      if (!c.pocket) return this.lab.status("click a pocket");
      $("plan-pocket").value = c.pocket.name;
      this.picking = "target";
      this.lab.status(`in ${c.pocket.name}: now click where the cue ball should stop`);
    } else {
      $("target-x").value = c.at[0].toFixed(4);
      $("target-y").value = c.at[1].toFixed(4);
      this.picking = null;
      $("pick").textContent = "Pick on table";
      this.lab.status("ready to plan");
    }
    this.picked = true;
    this.drawChoice();
  }

  async run() {
    if (this.lab.busy) return;
    const target = this.target();
    if (!target) return this.lab.status("choose a target for the cue ball first", true);
    const req = {
      scene: this.lab.scene(),
      pot: $("plan-pot").value,
      pocket: $("plan-pocket").value,
      target,
      cue_ball: this.lab.strike.ball,
      samples: Number($("samples").value),
      alternatives: Number($("alternatives").value),
    };
    this.running = true;
    this.cancelRequested = false;
    this.lab.lock(true);
    const bar = $("plan-progress");
    bar.hidden = false;
    bar.removeAttribute("value");
    try {
      const job = await api.post("/api/plan", req);
      this.job = job.id;
      // Cancel clicked before the job had its id.
      if (this.cancelRequested) await api.cancelJob(job.id).catch((e) => this.lab.fail(e));
      const end = await api.waitJob(job.id, (s) => {
        $("plan-status").textContent = `${s.state}: ${s.shots} shots simulated, ${s.elapsed.toFixed(1)} s`;
      });
      if (end.state === "done") {
        this.show(end.result);
        this.lab.status(`planned: ${end.result.plan.shots_simulated} shots in ${end.result.plan.wall_time.toFixed(2)} s`);
      } else if (end.state === "cancelled") {
        this.lab.status(`plan cancelled (${end.reason}) after ${end.shots} shots`);
      } else {
        this.lab.status(end.error ? end.error.message : `plan ${end.state}`, true);
      }
    } catch (e) {
      this.lab.fail(e);
    } finally {
      this.job = null;
      this.running = false;
      bar.hidden = true;
      this.lab.lock(false);
    }
  }

  async cancel() {
    if (!this.running) return;
    this.cancelRequested = true;
    if (this.job != null) await api.cancelJob(this.job).catch((e) => this.lab.fail(e));
  }

  // Draws the plan: the best shot's paths, the alternatives' cue ball paths, the spread.
  show(view) {
    this.result = view;
    const lab = this.lab;
    lab.stopAnimation();
    lab.restBalls();
    lab.table.clear("paths");
    lab.table.clear("aim");
    lab.table.clear("alternatives");
    lab.table.drawPaths(view.alternatives, "alternatives", "alt-path");
    lab.table.drawPaths(view.best.paths);
    lab.listEvents(view.best.result);
    lab.shot = view.best;
    lab.shotKept = false;
    this.drawChoice();
    const p = view.plan;
    const rows = [["best", p.best], ...p.alternatives.map((a, i) => [`alt ${i + 1}`, a])];
    const table = document.createElement("table");
    table.className = "alts";
    table.innerHTML =
      "<tr><th></th><th>P(pot)</th><th>miss, mm</th><th>spread, mm</th><th>speed</th><th>aim °</th><th>side, height mm</th></tr>";
    for (const [name, s] of rows) {
      const tr = table.insertRow();
      const r = s.robustness;
      const cells = [
        name,
        r ? r.pot_probability.toFixed(3) : "–",
        (s.distance * 1000).toFixed(1),
        r ? (r.cue_final_spread * 1000).toFixed(1) : "–",
        s.strike.speed.toFixed(3),
        (s.strike.aim / DEG).toFixed(3),
        `${(s.strike.offset[0] * 1000).toFixed(1)}, ${(s.strike.offset[1] * 1000).toFixed(1)}`,
      ];
      for (const c of cells) tr.insertCell().textContent = c;
    }
    const head = document.createElement("p");
    head.id = "plan-summary";
    head.textContent =
      `${p.reached ? "Reached" : "Not reached"}: ${p.pot} in ${p.pocket}, cue ball ends ` +
      `${(p.best.distance * 1000).toFixed(1)} mm from the target; ` +
      `${p.shots_simulated} shots simulated in ${p.wall_time.toFixed(2)} s.`;
    $("plan-result").replaceChildren(head, table);
    lab.refreshControls();
  }

  // Plays the planned shot: its strike set, the scene simulated again (it replays exactly).
  async playPlanned() {
    if (!this.result || this.lab.busy) return;
    this.lab.strikes.set(this.result.plan.best.strike);
    await this.lab.strikeNow();
  }

  wire() {
    $("pick").addEventListener("click", () => {
      this.picking = this.picking ? null : "ball";
      $("pick").textContent = this.picking ? "Picking… (click to stop)" : "Pick on table";
      if (this.picking) this.lab.status("click the ball to pot");
    });
    for (const id of ["plan-pot", "plan-pocket", "target-x", "target-y"]) {
      $(id).addEventListener("change", () => {
        this.picked = true;
        this.drawChoice();
      });
    }
    $("plan").addEventListener("click", () => this.run());
    $("plan-cancel").addEventListener("click", () => this.cancel());
    $("play-plan").addEventListener("click", () => this.playPlanned());
  }
}
