//! The cross-check report: a terminal table, the Markdown document (docs/validation.md) and
//! JSON.

use crate::compare::{Comparison, Figure};
use crate::convergence::{FIGURES, StepRow};
use crate::crosscheck::{Outcome, RunReport};
use crate::nose::NoseRebound;
use serde::Serialize;
use std::fmt::Write as _;

/// Everything one `snooker validate` produces.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// rapier's time step, s.
    pub dt: f64,
    /// One per (scene, models) run.
    pub runs: Vec<RunReport>,
    /// rapier's cushion rebound with the nose at 7R/5, frictionless (when measured).
    pub nose: Vec<NoseRebound>,
    /// The time-step study (when run).
    pub convergence: Vec<StepRow>,
}

impl Report {
    /// True when no run failed.
    pub fn pass(&self) -> bool {
        self.runs.iter().all(RunReport::pass)
    }

    /// Runs compared, passed, failed and skipped.
    pub fn counts(&self) -> (usize, usize, usize, usize) {
        let compared = self
            .runs
            .iter()
            .filter(|r| matches!(r.outcome, Outcome::Compared { .. }))
            .count();
        let skipped = self
            .runs
            .iter()
            .filter(|r| matches!(r.outcome, Outcome::Skipped { .. }))
            .count();
        let failed = self.runs.iter().filter(|r| !r.pass()).count();
        let passed = self
            .runs
            .iter()
            .filter(|r| matches!(r.outcome, Outcome::Compared { .. }) && r.pass())
            .count();
        (compared, passed, failed, skipped)
    }
}

/// The verdict word of a run.
pub fn verdict(r: &RunReport) -> &'static str {
    match &r.outcome {
        Outcome::Compared { .. } if r.pass() => "PASS",
        Outcome::Compared { .. } => "FAIL",
        Outcome::Skipped { .. } => "SKIP",
        Outcome::Failed { .. } => "ERROR",
    }
}

fn comparison(r: &RunReport) -> Option<&Comparison> {
    match &r.outcome {
        Outcome::Compared { comparison, .. } => Some(comparison),
        _ => None,
    }
}

/// "matched n" or "ours n / rapier m" for the compared impacts.
fn sequence_cell(c: &Comparison) -> String {
    let n = c.compared;
    if c.sequence_match {
        format!("{n} same")
    } else {
        format!("DIFFER ({n} vs {})", c.sequence_rapier.len().min(n.max(1)))
    }
}

/// The compact "diff / tol" of a figure, or "-" when the run has no such figure.
fn figure_cell(c: &Comparison, name: &str) -> String {
    match c.figures.iter().find(|f| f.name == name) {
        Some(f) => format!(
            "{} / {}{}",
            sci(f.diff),
            sci(f.tol),
            if f.pass() { "" } else { " **FAIL**" }
        ),
        None => "-".into(),
    }
}

/// A number in short scientific notation.
pub fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if x.is_infinite() {
        "inf".into()
    } else {
        format!("{x:.2e}")
    }
}

fn figure_line(f: &Figure) -> String {
    format!(
        "    {:<22} {:<34} ours {:>11.6} rapier {:>11.6} diff {:>9} tol {:>9} {}",
        f.name,
        f.at,
        f.ours,
        f.rapier,
        sci(f.diff),
        sci(f.tol),
        if f.pass() { "ok" } else { "FAIL" }
    )
}

/// The terminal table: one line per run, then each compared run's figures.
pub fn text(report: &Report) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<18} {:<13} {:<16} {:<7} details",
        "scene", "models", "impacts", "verdict"
    );
    for r in &report.runs {
        let (seq, detail) = match &r.outcome {
            Outcome::Compared {
                comparison, sink, ..
            } => (sequence_cell(comparison), format!("sink {} m", sci(*sink))),
            Outcome::Skipped { reason } | Outcome::Failed { reason } => {
                ("-".into(), reason.clone())
            }
        };
        let _ = writeln!(
            out,
            "{:<18} {:<13} {:<16} {:<7} {detail}",
            r.scene,
            r.models.name(),
            seq,
            verdict(r)
        );
        if let Some(c) = comparison(r) {
            for f in &c.figures {
                let _ = writeln!(out, "{}", figure_line(f));
            }
            if !c.sequence_match {
                let _ = writeln!(out, "    ours:   {}", c.sequence_ours.join(", "));
                let _ = writeln!(out, "    rapier: {}", c.sequence_rapier.join(", "));
            }
        }
        for s in &r.statistics {
            let _ = writeln!(
                out,
                "    statistic {:<30} ours {:.3} +- {:.3} [{:.3}, {:.3}]  rapier {:.3}",
                s.name, s.ours_mean, s.ours_sd, s.ours_min, s.ours_max, s.rapier
            );
        }
    }
    let (compared, passed, failed, skipped) = report.counts();
    let _ = writeln!(
        out,
        "\n{compared} runs compared at dt = {} s: {passed} passed, {failed} failed; {skipped} skipped",
        report.dt
    );
    out
}

/// The Markdown document: the method and its justification ([`METHOD`]), then the tables.
pub fn markdown(report: &Report) -> String {
    let mut out = String::new();
    let (compared, passed, failed, skipped) = report.counts();
    let _ = writeln!(out, "# Cross-check against rapier\n");
    let _ = writeln!(
        out,
        "Generated by `cargo run --release -- validate --convergence --markdown docs/validation.md`; \
         do not edit by hand.\n"
    );
    let why_skipped = if skipped > 0 {
        " (impact models not in the engine)"
    } else {
        ""
    };
    let _ = writeln!(
        out,
        "**Result:** {compared} runs compared at rapier time step dt = {} s: {passed} passed, \
         {failed} failed; {skipped} skipped{why_skipped}.\n",
        report.dt
    );
    out.push_str(METHOD);
    out.push_str("\n## Results, one row per run\n\n");
    out.push_str(
        "Each cell: the largest difference between the engines / its tolerance (the event or ball \
         where the ratio is worst is in the details below).\n\n",
    );
    let _ = write!(out, "| scene | models | impacts | verdict |");
    for f in FIGURES {
        let _ = write!(out, " {f} |");
    }
    out.push('\n');
    out.push_str("|---|---|---|---|");
    for _ in FIGURES {
        out.push_str("---|");
    }
    out.push('\n');
    for r in &report.runs {
        let _ = write!(out, "| {} | {} |", r.scene, r.models.name());
        match comparison(r) {
            Some(c) => {
                let _ = write!(out, " {} | {} |", sequence_cell(c), verdict(r));
                for f in FIGURES {
                    let _ = write!(out, " {} |", figure_cell(c, f));
                }
            }
            None => {
                let _ = write!(out, " - | {} |", verdict(r));
                for _ in FIGURES {
                    out.push_str(" - |");
                }
            }
        }
        out.push('\n');
    }
    details(&mut out, report);
    statistics(&mut out, report);
    nose(&mut out, report);
    convergence(&mut out, report);
    out
}

fn details(out: &mut String, report: &Report) {
    out.push_str("\n## Details\n\n");
    out.push_str(
        "Values at the worst event: times in s, velocities in m/s (vector norms), spins in \
         rad/s, final positions as the distance of the plan position from the origin (the \
         difference is the distance between the two positions).\n",
    );
    for r in &report.runs {
        match &r.outcome {
            Outcome::Compared {
                comparison: c,
                sink,
                steps,
                rapier_finished,
                ..
            } => {
                let _ = writeln!(
                    out,
                    "\n### {} ({})\n\nImpacts (ours): {}. rapier: {} steps, sink {} m{}.\n",
                    r.scene,
                    r.models.name(),
                    if c.sequence_ours.is_empty() {
                        "none".into()
                    } else {
                        c.sequence_ours.join(", ")
                    },
                    steps,
                    sci(*sink),
                    if *rapier_finished {
                        ""
                    } else {
                        "; **the balls had not stopped**"
                    }
                );
                if !c.sequence_match {
                    let _ = writeln!(
                        out,
                        "**Sequences differ** (first {} compared). rapier: {}.\n",
                        c.compared,
                        c.sequence_rapier.join(", ")
                    );
                }
                out.push_str("| figure | at | ours | rapier | difference | tolerance | ok |\n");
                out.push_str("|---|---|---|---|---|---|---|\n");
                for f in &c.figures {
                    let _ = writeln!(
                        out,
                        "| {} ({}) | {} | {:.6} | {:.6} | {} | {} | {} |",
                        f.name,
                        f.unit,
                        f.at,
                        f.ours,
                        f.rapier,
                        sci(f.diff),
                        sci(f.tol),
                        if f.pass() { "yes" } else { "**no**" }
                    );
                }
            }
            Outcome::Skipped { reason } | Outcome::Failed { reason } => {
                let what = if matches!(r.outcome, Outcome::Skipped { .. }) {
                    "Skipped"
                } else {
                    "**Error**"
                };
                let _ = writeln!(
                    out,
                    "\n### {} ({})\n\n{what}: {reason}.",
                    r.scene,
                    r.models.name()
                );
            }
        }
    }
}

fn statistics(out: &mut String, report: &Report) {
    for r in report.runs.iter().filter(|r| !r.statistics.is_empty()) {
        let _ = writeln!(
            out,
            "\n## Outcome statistics of {} ({}), measured\n",
            r.scene,
            r.models.name()
        );
        out.push_str(STATISTICS);
        out.push_str(
            "\n| statistic | ours: mean | sd | min | max | rapier |\n|---|---|---|---|---|---|\n",
        );
        for s in &r.statistics {
            let _ = writeln!(
                out,
                "| {} | {:.3} | {:.3} | {:.3} | {:.3} | {:.3} |",
                s.name, s.ours_mean, s.ours_sd, s.ours_min, s.ours_max, s.rapier
            );
        }
    }
}

fn nose(out: &mut String, report: &Report) {
    if report.nose.is_empty() {
        return;
    }
    out.push_str("\n## rapier's cushion rebound with the nose at 7R/5, frictionless, measured\n\n");
    out.push_str(NOSE);
    out.push_str("\n| scene | cushion | approach (m/s) | ours: after/before | rapier: after/before |\n|---|---|---|---|---|\n");
    for n in &report.nose {
        let _ = writeln!(
            out,
            "| {} | {} | {:.4} | {:.4} | {:.4} |",
            n.scene, n.cushion, n.approach, n.ours, n.rapier
        );
    }
}

fn convergence(out: &mut String, report: &Report) {
    if report.convergence.is_empty() {
        return;
    }
    out.push_str("\n## Time-step study\n\n");
    out.push_str(CONVERGENCE);
    let _ = write!(out, "\n| dt (s) |");
    for f in FIGURES {
        let _ = write!(out, " {f} |");
    }
    out.push_str(" passed | time (s) |\n|---|");
    for _ in FIGURES {
        out.push_str("---|");
    }
    out.push_str("---|---|\n");
    for row in &report.convergence {
        let _ = write!(out, "| {} |", row.dt);
        for d in &row.max_diff {
            let _ = write!(out, " {} |", sci(*d));
        }
        let _ = writeln!(out, " {}/{} | {:.1} |", row.passed, row.runs, row.seconds);
    }
}

/// How the cross-check works and why its tolerances are what they are.
pub const METHOD: &str = r#"## What is compared

Every scene of `validation/scenes/` is simulated by our event-driven engine and by
[rapier](https://rapier.rs) (`rapier3d-f64` 0.36.1), built from the same `Setup`:

- **Balls**: dynamic spheres of the scene's radius and mass (rapier's solid-sphere inertia is
  2MR²/5, as ours). **Cloth**: a fixed half-space. **Pockets**: sensor spheres of radius
  (fall radius − R) at the height of a ball's centre, so that a ball overlaps one exactly when
  its centre enters the fall circle, the engine's rule; the ball is then removed.
- **Cushions and jaws**: capsules along each nose and facing, and spheres at the jaws, placed so
  that a ball on the cloth touches them where the engine says (centre R cos θ from the nose line
  in plan, jaw contact r_j + R cos θ from the jaw centre). With friction on they touch at the
  nose height h = 7R/5 with the normal tilted by θ (thesis §6.2). In the frictionless limit
  they touch level with the ball's centre (see "By-design differences").
- **Friction and restitution** per pair from the scene's parameters (a contact hook): cloth
  μ_s, no bounce; ball-ball e and, with friction, μ_bb; cushion e_e and, with friction, μ_w.
  In the frictionless limit the ball-ball and cushion friction are zero.
- **What rapier lacks**, applied as external loads every step: rolling resistance (force
  −Mμ_r g v̂ and torque −(Iμ_r g/R) e_z × v̂ on a rolling ball, which keeps it rolling while it
  decelerates at μ_r g, thesis §2.4.2) and the cloth's resistance to sidespin (torque −I·22 rad/s²
  about the vertical, thesis §5.3), each clamped so that a step never reverses the motion.
  rapier's friction model is set to Coulomb (one friction cone per contact, no twist constraint),
  contact recycling off.

From each engine's run the same record is taken: the impacts in order (ball pairs, cushions or
jaws by name, pots by pocket), their times, every involved ball's velocity and spin just after,
the slide-to-roll times and speeds, and the final positions. rapier's events are read from its
steps: an impact starts in the step in which a contact first carries an impulse (its time is
where the gap before the step, closing at the approach speed, reaches zero); a ball rolls while
its cloth contact sticks (friction below the Coulomb limit) with a slip below one step's worth
(3.5 μ_s g dt); a pot is the step in which the ball overlaps a pocket sensor. Both records are
reduced to what both can resolve: contacts closing slower than 2 mm/s (twice our engine's
micro-collision speed `MIN_SEPARATION`) are resting contacts, and repeats of one contact within
two steps are one impact.

**Time step.** dt = 10⁻⁴ s, from the study at the end: halving the step from 4×10⁻⁴ s
halves the largest differences (the step's share dominates), from 10⁻⁴ s on a halving changes
them by a third or less and far inside their tolerances (the soft contact's share, which does
not depend on dt, dominates), and the whole set takes about 15 s, which keeps the integration
tests (`validation/tests/crosscheck.rs`) within the CI budget.

The verdict of a run passes when the impact sequences are identical and every figure is within
its tolerance; `snooker validate` exits non-zero otherwise.

## Tolerances, derived

Each tolerance is computed event by event from our engine's record and the known differences
between the runs; none is a fitted number. With a_s = μ_s g, a_r = μ_r g:

- **Time step.** rapier resolves every discrete change (impact, start of rolling, pot) at a step
  boundary: each may shift by one step dt, and within a step the cloth's friction changes a speed
  by up to a_s dt and a sliding ball's spin by 5a_s dt/2R. rapier's state after an impact is the
  state at the end of that step.
- **Soft contact.** A ball sinks δ into rapier's cloth (the largest depth seen in the run,
  about 6.9×10⁻⁵ m: the static deflection g/(2π·60 Hz)² of rapier's contact spring against a
  fixed body) and rapier puts the contact point at mid-depth: the ball rolls on R' = R(1 − ε),
  ε = δ/2R. From the conservation of angular momentum about the contact point, the rolling
  speed (k²v₀ + 0.4kω₀R)/(k² + 0.4), k = R'/R, moves by at most ε(0.41|v₀| + 0.13|ω₀|R); the
  sliding time by at most ε(|ω₀|R/3.5a_s + 1.43 t_slide); while sliding, the friction's torque
  arm is R' too, so the spin drifts by ε(5a_s/2R) per second of sliding.
- **Propagation.** A speed error dv carried over a stretch of travel τ arriving at speed v shifts
  the arrival by τ dv/v; an impact passes velocity errors on with gain at most 1 (Newton's law,
  equal masses) plus a_s times its time error; a ball rolling to rest from speed v with a speed
  error dv stops v dv/a_r further or shorter and up to (v²/2a_r)(dv/v) to the side, and a time
  error t' of the start of its roll moves it by v t'. The bounds accumulate in time order over
  all balls (conservatively).
- **Level cushions under a sunk ball.** The sunk ball meets a level cushion slightly below its
  axis: the normal tilts by δ/(R + r_c), giving a vertical velocity of up to (1 + e)v_n δ/(R + r_c).
- **With friction (by design).** Newton's restitution with Coulomb friction resolved
  once per time step (rapier) against energetic restitution with Coulomb friction integrated
  over the normal impulse, its slip directions free to turn (ours, thesis §6.1, §6.2): each engine's friction impulse is at most μ times the normal impulse, so
  the velocities after an impact may differ by up to twice that (2μ(1 + e)v_n/2 for a ball pair,
  2(μ_w + μ_s sin θ)(1 + e)v_n/cos θ at a cushion) and the spins by 5/2R times it; the difference
  is carried forward like any other. These runs measure the difference; their bound only
  catches a difference no friction can explain.

## By-design differences

- **Restitution.** In the frictionless limit Newton's and the energetic (Stronge) restitution
  coincide, so both engines must agree to the tolerances above. With friction they differ by
  design; those runs report the measured difference.
- **Cushion contact height in the frictionless limit.** rapier applies restitution once per
  step, after its solve, one contact at a time (an end-of-step restitution pass in the manner
  of Box2D). At a nose at 7R/5 the bounce along the tilted normal pushes the ball into the
  cloth, and the cloth takes that vertical velocity away inelastically in the next step: rapier
  loses part of the rebound (measured below), where the rigid answer (nose and cloth solved
  together) reverses the plan normal velocity with e exactly, as our engine does. Without
  friction a level contact is the same impact (the nose's push plus the cloth's reaction is a
  horizontal impulse through the centre either way), so the frictionless runs use level
  cushions; the runs with friction, where the contact height matters, use the nose at 7R/5.
- **Touching balls.** Our engine resolves a pack as a sequence of pairwise impacts; rapier solves
  all contacts of a step together. The break-off is compared up to the first impact on the
  pack (which ball, when), not the states after it; its outcome is chaotic and is compared
  through statistics (measured, no verdict).
- **Soft contact.** The sink δ above; rapier's balls rest δ lower, so final positions are
  compared in plan.
"#;

const STATISTICS: &str = "Once the pack is struck, tiny differences grow until individual \
outcomes have nothing in common. Our engine is run on an ensemble of the shot with the cue \
ball's heading turned by multiples of 10⁻⁴ rad (−8 … 8, far below a player's aim) and rapier's \
outcome is set beside the ensemble. Ball-ball impact counts are not comparable by construction: \
rapier's pack contacts start from rest and carry force without an approach speed, so they do \
not count as impacts. The number of balls that moved is where the engines really differ, and \
we attribute it to the treatment of touching balls: pairwise sequential impacts (ours) pass the \
momentum along each line of centres in turn and eject the far balls of the pack, while rapier's \
simultaneous solve shares it among all the touching balls at once, which then move off more \
together. The rigid-body model does not decide between the two (simultaneous contacts of rigid \
balls have no unique outcome); which is closer to real balls is a question for measured \
break-offs, not for this cross-check.\n";

const NOSE: &str = "The first cushion impact of each cushion scene, frictionless, rapier's \
cushions at the nose height 7R/5 (cloth friction off during the impact, as the frictionless \
limit asks): the plan normal velocity after the impact over the one before. Ours is the scene's \
e_e = 0.98 (rolling resistance aside); rapier's end-of-step restitution pass loses the vertical \
part of the bounce to the cloth (see \"By-design differences\"), which is why the frictionless \
comparison uses level cushions.\n";

const CONVERGENCE: &str = "The scene set in the frictionless limit at halving time steps: the \
largest difference between the engines of each figure over all scenes (the break-off's first \
impact included). The differences shrink with dt until the soft contact's share (the sink, \
independent of dt) dominates; the default step is where they have settled.\n";
