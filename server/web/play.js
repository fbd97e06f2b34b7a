// The Play panel: a frame of snooker played stroke by stroke with the strike set by hand; the
// rules crate's referee judges each stroke (verdict, foul, points, scores, who plays next) and
// gives the frame that follows. The player's visits (player.js) are shown here too: in a frame
// against the player, its turn comes after a hand stroke that gives it the table.

import * as api from "./api.js";

const $ = (id) => document.getElementById(id);

export class PlayPanel {
  constructor(lab) {
    this.lab = lab;
    this.strokes = 0;
  }

  setPosition(position) {
    const f = position.frame;
    const board = $("scoreboard");
    const nom = $("nominate");
    if (!f) {
      board.textContent = "Not a frame of snooker: load break-off or open-table to play.";
      nom.replaceChildren();
      nom.disabled = true;
      return;
    }
    board.textContent =
      `Player 0: ${f.scores[0]} · Player 1: ${f.scores[1]} — player ${f.to_play} to play, ` +
      `on ${f.on}${f.free_ball ? " (free ball)" : ""}${f.ball_in_hand ? ", cue ball in hand (drag it within the D)" : ""}`;
    const noms = (position.rules && position.rules.nominations) || [];
    const needs = f.on === "colour" || f.free_ball;
    nom.replaceChildren(...noms.map((c) => new Option(c, c)));
    // A free ball may be declined (WPBSA Section 3 Rule 12(b)): the ball on is played.
    if (f.free_ball) nom.prepend(new Option("none: decline the free ball", ""));
    nom.disabled = !needs || noms.length === 0;
    if (needs && noms.length) {
      // The frame's own nomination (a pasted play-log line's), else the black, else the last.
      const own = f.nominated;
      nom.value = noms.includes(own) ? own : noms.includes("black") ? "black" : noms[noms.length - 1];
    }
  }

  // The frame of the request: the position, its [frame] table, the strike.
  frame() {
    const lab = this.lab;
    const f = structuredClone(lab.position.frame);
    const needs = f.on === "colour" || f.free_ball;
    if (needs) f.nominated = $("nominate").value;
    if (f.free_ball && !f.nominated) f.free_ball = false; // declined: the ball on is played
    if (!f.nominated) delete f.nominated;
    const scene = lab.scene();
    scene.frame = f;
    return scene;
  }

  // The stroke: the page stays busy from the request to the end of its animation, when the
  // frame it leaves becomes the position (a stroke asked meanwhile would be of the frame before).
  async stroke() {
    const lab = this.lab;
    if (!lab.position.frame || lab.busy || lab.frameOver) return;
    lab.lock(true);
    let animated = false;
    try {
      lab.status("playing the stroke…");
      const v = await api.post("/api/frame/stroke", { frame: this.frame() });
      this.strokes += 1;
      this.showVerdict(v.referee);
      animated = true;
      lab.showShot(v.shot, () => {
        if (v.next) {
          lab.setPosition(v.next, "the frame after the stroke");
          // The stroke stays shown over the position it left, and can be replayed.
          lab.keepShot(v.shot);
        } else this.over(v.referee);
        lab.lock(false);
        lab.player.takeTurn();
      });
      lab.status(v.referee.legal ? "legal stroke" : `foul: ${v.referee.foul.reason}`);
    } catch (e) {
      lab.fail(e);
    } finally {
      if (!animated) lab.lock(false);
    }
  }

  // The referee's verdict `r` of a stroke, said of `who` (the hand stroke's when not given).
  showVerdict(r, who = null) {
    const d = $("verdict");
    const p = document.createElement("p");
    p.id = "verdict-line";
    p.className = r.legal ? "legal" : "foul";
    const potted = r.potted.length ? `potted ${r.potted.join(", ")}` : "nothing potted";
    const first = r.first_hit ? `first hit ${r.first_hit}` : "no ball hit";
    p.textContent = r.legal
      ? `Legal: ${first}, ${potted}, ${r.points} points. Scores ${r.scores[0]}–${r.scores[1]}.`
      : `Foul (${r.foul.reason}, ${r.foul.points} to the opponent): ${first}, ${potted}. Scores ${r.scores[0]}–${r.scores[1]}.`;
    if (who) p.textContent = `${who}: ${p.textContent}`;
    d.replaceChildren(p);
    const li = document.createElement("li");
    li.textContent = p.textContent;
    $("strokes").appendChild(li);
  }

  // The frame is over: no more strokes, by hand or by the player, until a new position.
  over(r) {
    $("scoreboard").textContent = `Frame over: player ${r.winner} wins, ${r.scores[0]}–${r.scores[1]}.`;
    this.lab.frameOver = true;
    this.lab.refreshControls();
  }

  wire() {
    $("new-frame").addEventListener("click", () => {
      this.strokes = 0;
      $("strokes").replaceChildren();
      $("verdict").replaceChildren();
      $("player-reasoning").replaceChildren();
      this.lab.loadLayout("break-off").then(() => this.lab.player.takeTurn());
    });
    $("play-stroke").addEventListener("click", () => this.stroke());
  }
}
