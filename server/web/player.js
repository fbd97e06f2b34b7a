// The player (the player crate, `snooker play`) in the Play panel: its visit from the page's
// frame, run as a job on the server that reports each stroke as it is played. Each stroke is
// animated like a hand-played one, with the referee's verdict and the score, and the player's
// reasoning from its typed Decision: the stroke chosen (kind, balls, pocket, nomination, where
// the cue ball in hand went, pot probability, expected value) and the alternatives it
// considered with their values. Nothing here is computed: every number is the server's.
// In a frame against the player, its visits start by themselves when its side is to play.

import * as api from "./api.js";

const $ = (id) => document.getElementById(id);
const DEG = 180 / Math.PI;

// What a stroke was planned as, in words (a Considered of the player crate).
export function describe(c) {
  const via = c.via && c.via.length ? ` off ${c.via.join(", ")}` : "";
  switch (c.kind) {
    case "safety":
      // An escape from a snooker names the cushions the cue ball meets first.
      return `safety off ${c.ball}${c.via && c.via.length ? ` via ${c.via.join(", ")}` : ""}`;
    case "plant":
      return `plant: ${c.ball} onto ${c.pot} in ${c.pocket}`;
    case "double":
      return `double: ${c.pot}${via} in ${c.pocket}`;
    case "kiss":
      return `kiss: ${c.pot}${via} in ${c.pocket}`;
    default:
      return `${c.kind}: ${c.pot} in ${c.pocket}`;
  }
}

function strike(s) {
  return (
    `${s.speed.toFixed(3)} m/s, aim ${(s.aim * DEG).toFixed(3)}°, ` +
    `side ${(s.offset[0] * 1000).toFixed(1)} mm, height ${(s.offset[1] * 1000).toFixed(1)} mm`
  );
}

// A table cell showing `value` to `digits` decimals, the exact number kept in data-value.
function numberCell(tr, value, digits, field) {
  const td = tr.insertCell();
  td.textContent = value.toFixed(digits);
  td.dataset.value = String(value);
  td.dataset.field = field;
  return td;
}

export class PlayerPanel {
  constructor(lab) {
    this.lab = lab;
    this.job = null;
    // From the click to the visit's end (the job's id comes later).
    this.running = false;
    this.cancelRequested = false;
    this.parts = [];
  }

  setInfo(info) {
    const l = info.limits;
    const effort = $("player-effort");
    effort.max = String(l.play_effort);
    if (!effort.value) effort.value = String(l.play_effort_default);
    this.lab.refreshControls();
  }

  setPosition() {
    this.lab.refreshControls();
  }

  // The frame the player plays from: the position with its [frame] table; the player places
  // the cue ball in hand and nominates for itself.
  frame() {
    const scene = structuredClone(this.lab.position.scene);
    delete scene.cue;
    const f = structuredClone(this.lab.position.frame);
    delete f.nominated;
    scene.frame = f;
    return scene;
  }

  // In a frame against the player: its visit, when its side is to play.
  takeTurn() {
    const f = this.lab.position && this.lab.position.frame;
    if (!$("vs-player").checked || !f || this.running || this.lab.frameOver) return;
    if (f.to_play === Number($("player-side").value)) this.visit();
  }

  async visit() {
    const lab = this.lab;
    if (!lab.position || !lab.position.frame || this.running || lab.busy || lab.frameOver) return;
    this.running = true;
    this.cancelRequested = false;
    lab.lock(true);
    const req = {
      frame: this.frame(),
      effort: Number($("player-effort").value),
      seed: Number($("player-seed").value),
      noise: $("player-noise").value,
    };
    const side = lab.position.frame.to_play;
    const bar = $("player-progress");
    bar.hidden = false;
    bar.removeAttribute("value");
    this.parts = [];
    let seen = 0;
    let last = null;
    try {
      const job = await api.post("/api/play", req);
      this.job = job.id;
      // Cancel clicked before the job had its id.
      if (this.cancelRequested) await api.cancelJob(job.id).catch((e) => lab.fail(e));
      lab.status(`player ${side}'s visit: seed ${req.seed}, effort ${req.effort}, noise ${req.noise}`);
      for (;;) {
        const s = await api.get(`/api/jobs/${job.id}?since=${seen}`);
        $("player-status").textContent =
          `${s.state}: ${s.shots} shots simulated, ${s.reported} strokes, ${s.elapsed.toFixed(1)} s` +
          (s.note ? ` — ${s.note}` : "");
        for (const part of s.parts || []) {
          seen += 1;
          this.parts.push(part);
          await this.show(part);
        }
        if (s.state !== "queued" && s.state !== "running" && seen >= s.reported) {
          last = s;
          break;
        }
        await new Promise((r) => setTimeout(r, 150));
      }
      const played = this.parts.length;
      if (last.state === "done") {
        const r = last.result;
        lab.status(
          `player ${side}'s visit over: ${r.strokes} strokes, ${r.points} points ` +
            `(${r.end.replace("_", " ")}; seed ${r.seed}, ${r.shots_simulated} shots)`,
        );
      } else if (last.state === "cancelled") {
        lab.status(`the player's visit cancelled (${last.reason}) after ${last.shots} shots; ${played} strokes played`);
      } else {
        lab.status(last.error ? last.error.message : `the player's visit ${last.state}`, true);
      }
      $("player-status").textContent = `${last.state}: ${last.shots} shots simulated, ${played} strokes`;
    } catch (e) {
      lab.fail(e);
    } finally {
      this.job = null;
      this.running = false;
      bar.hidden = true;
      // The hand strokes again, unless the frame is over (the scoreboard says who won).
      lab.lock(false);
    }
  }

  async cancel() {
    if (!this.running) return;
    this.cancelRequested = true;
    if (this.job != null) await api.cancelJob(this.job).catch((e) => this.lab.fail(e));
  }

  // One stroke of the player: the frame it was played from (the cue ball where it placed it),
  // its reasoning, the shot animated, then the verdict, the score and the frame that follows.
  show(part) {
    const lab = this.lab;
    return new Promise((done) => {
      lab.setPosition(part.before, `the player's stroke ${part.number}`);
      this.reasoning(part);
      const to = part.decision.plan.cue_to;
      const R = lab.table.view.ball_radius;
      lab.table.mark("circle", { cx: to[0], cy: to[1], r: R, class: "target", id: "player-target" });
      lab.showShot(part.shot, () => {
        lab.play.showVerdict(part.referee, `Player ${part.player}'s stroke ${part.number} (the player)`);
        if (part.next) {
          lab.setPosition(part.next, `after the player's stroke ${part.number}`);
          lab.keepShot(part.shot);
        } else {
          lab.play.over(part.referee);
        }
        done();
      });
    });
  }

  // The player's reasoning for `part`: the stroke chosen and the alternatives considered.
  reasoning(part) {
    const d = part.decision;
    const p = d.plan;
    const head = document.createElement("p");
    head.id = "player-chosen";
    const extras = [];
    if (d.cue_ball) extras.push(`cue ball in hand placed at (${d.cue_ball[0].toFixed(4)}, ${d.cue_ball[1].toFixed(4)})`);
    if (d.nominated) extras.push(`nominated ${d.nominated}`);
    head.textContent =
      `Stroke ${part.number} (player ${part.player}): ${describe(p)}` +
      (extras.length ? `; ${extras.join("; ")}` : "") +
      `. Pot probability ${p.pot_probability.toFixed(3)}, expected value ${p.value.toFixed(3)} points ` +
      `(the points and the position left, the mean of ${p.samples} noise samples); ` +
      `${d.shots_simulated} shots in ${part.decision_time.toFixed(2)} s.`;
    const meant = document.createElement("p");
    meant.className = "about";
    meant.textContent = `Meant: ${strike(d.strike)}. Played (with the noise): ${strike(part.executed)}.`;
    const table = document.createElement("table");
    table.className = "alts";
    table.id = "player-considered";
    table.innerHTML =
      "<tr><th></th><th>stroke</th><th>P(pot)</th><th>value, points</th><th>samples</th><th>cue ball to</th></tr>";
    const rows = [["chosen", p], ...d.alternatives.map((a, i) => [`alt ${i + 1}`, a])];
    for (const [name, c] of rows) {
      const tr = table.insertRow();
      tr.dataset.row = name === "chosen" ? "chosen" : "alternative";
      tr.insertCell().textContent = name;
      tr.insertCell().textContent = describe(c);
      numberCell(tr, c.pot_probability, 3, "pot_probability");
      numberCell(tr, c.value, 3, "value");
      tr.insertCell().textContent = String(c.samples);
      tr.insertCell().textContent = `(${c.cue_to[0].toFixed(3)}, ${c.cue_to[1].toFixed(3)})`;
    }
    const note = document.createElement("p");
    note.className = "hint";
    note.textContent = d.alternatives.length
      ? "The alternatives are the next best strokes it weighed, best first."
      : "It weighed no other stroke.";
    $("player-reasoning").replaceChildren(head, meant, table, note);
  }

  wire() {
    $("player-visit").addEventListener("click", () => this.visit());
    $("player-cancel").addEventListener("click", () => this.cancel());
    $("vs-player").addEventListener("change", () => this.takeTurn());
    $("player-side").addEventListener("change", () => this.takeTurn());
  }
}
