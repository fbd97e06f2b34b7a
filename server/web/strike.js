// The strike controls: the struck ball, the aim (typed, or dragged on the table), the speed,
// the elevation, and the tip offset on the ball face, kept inside the miscue limit that the
// server reports (thesis eq. 7.7; the scene crate refuses a miscue either way).

const NS = "http://www.w3.org/2000/svg";
const DEG = Math.PI / 180;

export class StrikeControls {
  constructor(lab) {
    this.lab = lab;
    this.strike = { ball: "cue", speed: 2.0, aim: 0.0, offset: [0, 0], elevation: 0.0 };
    this.$ball = document.getElementById("cue-ball");
    this.$aim = document.getElementById("aim");
    this.$speed = document.getElementById("speed");
    this.$elev = document.getElementById("elevation");
    this.$face = document.getElementById("face");
    this.$ball.addEventListener("change", () => {
      this.strike.ball = this.$ball.value;
      lab.redrawAim();
    });
    this.$aim.addEventListener("change", () => {
      const v = Number(this.$aim.value);
      if (Number.isFinite(v)) this.setAim(v * DEG);
    });
    this.$speed.addEventListener("input", () => {
      this.strike.speed = Number(this.$speed.value);
      this.show();
    });
    this.$elev.addEventListener("input", () => {
      this.strike.elevation = Number(this.$elev.value) * DEG;
      this.show();
    });
    document.getElementById("centre").addEventListener("click", () => {
      this.strike.offset = [0, 0];
      this.show();
    });
    let dragging = false;
    const setFromEvent = (e) => {
      const m = this.$face.getScreenCTM().inverse();
      const p = new DOMPoint(e.clientX, e.clientY).matrixTransform(m);
      this.setOffsetFace(p.x, -p.y);
    };
    this.$face.addEventListener("pointerdown", (e) => {
      dragging = true;
      this.$face.setPointerCapture(e.pointerId);
      setFromEvent(e);
    });
    this.$face.addEventListener("pointermove", (e) => dragging && setFromEvent(e));
    this.$face.addEventListener("pointerup", () => (dragging = false));
    this.drawFace();
  }

  // The offset from a point on the face in units of the ball radius (x right, y up).
  setOffsetFace(fx, fy) {
    const t = this.lab.position.table;
    const R = t.ball_radius;
    const limit = (0.97 * t.miscue_radius) / R;
    const r = Math.hypot(fx, fy);
    const k = r > limit ? limit / r : 1;
    this.strike.offset = [fx * k * R, fy * k * R];
    this.show();
  }

  setAim(aim) {
    // The heading in (-pi, pi].
    let a = Math.atan2(Math.sin(aim), Math.cos(aim));
    this.strike.aim = a;
    this.show();
    this.lab.redrawAim();
  }

  set(strike) {
    this.strike = {
      ball: strike.ball,
      speed: strike.speed,
      aim: strike.aim,
      offset: [strike.offset[0], strike.offset[1]],
      elevation: strike.elevation,
    };
    // The selector shows the ball struck (a file's strike may be on another ball).
    if ([...this.$ball.options].some((o) => o.value === strike.ball)) this.$ball.value = strike.ball;
    this.show();
    this.lab.redrawAim();
  }

  setBalls(ids) {
    const keep = this.strike.ball;
    this.$ball.replaceChildren(
      ...ids.map((id) => {
        const o = document.createElement("option");
        o.value = o.textContent = id;
        return o;
      }),
    );
    this.strike.ball = ids.includes(keep) ? keep : ids.includes("cue") ? "cue" : ids[0] || "cue";
    this.$ball.value = this.strike.ball;
  }

  drawFace() {
    const f = this.$face;
    f.replaceChildren();
    const add = (name, attrs) => {
      const e = document.createElementNS(NS, name);
      for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
      f.appendChild(e);
      return e;
    };
    add("circle", { cx: 0, cy: 0, r: 1, class: "face" });
    add("line", { x1: -1, y1: 0, x2: 1, y2: 0, class: "cross" });
    add("line", { x1: 0, y1: -1, x2: 0, y2: 1, class: "cross" });
    this.$ring = add("circle", { cx: 0, cy: 0, r: 0.5, class: "miscue" });
    this.$tip = add("circle", { cx: 0, cy: 0, r: 0.09, class: "tip", id: "tip" });
  }

  show() {
    const s = this.strike;
    const t = this.lab.position && this.lab.position.table;
    this.$aim.value = (s.aim / DEG).toFixed(2);
    this.$speed.value = s.speed;
    document.getElementById("speed-out").textContent = `${s.speed.toFixed(2)} m/s`;
    this.$elev.value = s.elevation / DEG;
    document.getElementById("elevation-out").textContent = `${(s.elevation / DEG).toFixed(1)}°`;
    document.getElementById("offset-out").textContent =
      `side ${(s.offset[0] * 1000).toFixed(1)} mm, height ${(s.offset[1] * 1000).toFixed(1)} mm`;
    if (t) {
      const R = t.ball_radius;
      this.$ring.setAttribute("r", t.miscue_radius / R);
      this.$tip.setAttribute("cx", s.offset[0] / R);
      this.$tip.setAttribute("cy", -s.offset[1] / R);
    }
  }
}
