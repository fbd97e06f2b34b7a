//! The deterministic search for pots (steps 2–4 of docs/playing.md, "How a stroke is chosen"):
//! every line the planner's geometry leaves open tried on a coarse grid of strokes, the best
//! lines on a fine grid, the best strokes refined between the grid's points by Nelder–Mead;
//! each stroke valued without noise by the points and the position it leaves
//! ([`PotObjective`]), the position counted over the spread of the cue ball's end
//! ([`crate::spread`]).

use crate::agent::Context;
use crate::candidates::{self, ELEVATION, LineCandidate, Target};
use crate::outcome::outcome;
use crate::spread::{Spread, SpreadModel, end_shifts};
use crate::value::Valuer;
use rayon::prelude::*;
use snooker_engine::{EventKind, Shot, Vec3};
use snooker_planner::{Objective, Problem, Scored, Stroke, Trial, explore, refine};
use snooker_rules::{Frame, Next};

/// Lines explored at a time (in parallel; the budget is checked between batches).
const LINE_BATCH: usize = 4;
/// The coarse grid every line is tried with first: cue speeds (m/s), heights (shares of the
/// bounds' reach: screw to follow), no side.
const COARSE_SPEEDS: [f64; 4] = [0.5, 1.0, 1.9, 3.5];
const COARSE_HEIGHTS: [f64; 3] = [-0.7, 0.0, 0.7];
/// The fine grid the best lines get then: speeds, heights and sides (shares of the reach).
const FINE_SPEEDS: [f64; 8] = [0.35, 0.5, 0.7, 1.0, 1.4, 1.9, 2.6, 3.6];
const FINE_HEIGHTS: [f64; 5] = [-0.8, -0.4, 0.0, 0.4, 0.8];
const FINE_SIDES: [f64; 3] = [-0.5, 0.0, 0.5];
/// Share of the deterministic search's budget the coarse pass may spend.
const COARSE_SHARE: f64 = 0.35;
/// Lines given the fine grid at most.
const FINE_LINES: usize = 6;
/// Most strokes of one line taken to the noise samples.
const PER_LINE: usize = 2;
/// The best candidates of the grids refined by Nelder–Mead before the noise samples, the
/// iterations each and the first simplex's size (share of each of the stroke's ranges: speed
/// geometric, side, height). Measured: over open tables 1-200 at the standard noise the mean
/// break rose from 20.0 to 25.1 (paired, +5.2 ± 4.4 at 95 %; docs/playing.md).
const REFINED: usize = 6;
const REFINE_ITERS: u64 = 20;
const REFINE_SIZE: f64 = 0.08;

/// The pot's value to the player, without noise: the stroke must pot the ball on legally;
/// its value is the points and the position left, counted as robust to the speed's noise
/// ([`Valuer::robust`]).
struct PotObjective<'a> {
    frame: &'a Frame,
    valuer: &'a Valuer,
    pot: &'a str,
    /// Over which spread the cue ball's end is valued.
    spread: SpreadModel,
}

/// The cue ball's way in `shot` after its first contact: the length of its path from there to
/// where it stopped, and the unit heading of its last leg (from its last impact).
fn cue_path(shot: &Shot, cue: usize) -> (f64, Vec3) {
    let p = &shot.params;
    let track = &shot.tracks[cue];
    let impacts: Vec<f64> = shot
        .events
        .iter()
        .filter(|e| {
            e.balls.contains(&cue) && matches!(e.kind, EventKind::BallBall | EventKind::BallCushion)
        })
        .map(|e| e.t)
        .collect();
    let (Some(&first), Some(&last)) = (impacts.first(), impacts.last()) else {
        return (0.0, Vec3::zeros());
    };
    // The path's length, sampled finely enough for a cushion's corner.
    const STEPS: usize = 64;
    let mut length = 0.0;
    let mut prev = track.state_at(first, p).pos;
    for k in 1..=STEPS {
        let t = first + (shot.duration - first) * k as f64 / STEPS as f64;
        let q = track.state_at(t, p).pos;
        length += (q - prev).xy().norm();
        prev = q;
    }
    let a = track.state_at(last, p).pos;
    let d = (prev - a).xy();
    let n = d.norm();
    let heading = if n > 0.0 {
        Vec3::new(d.x / n, d.y / n, 0.0)
    } else {
        Vec3::zeros()
    };
    (length, heading)
}

impl<'a> PotObjective<'a> {
    /// The objective of potting `target`'s ball, the end valued over `spread`.
    fn new(target: &'a Target, valuer: &'a Valuer, spread: SpreadModel) -> Self {
        PotObjective {
            frame: &target.frame,
            valuer,
            pot: &target.frame.balls()[target.ball].id,
            spread,
        }
    }
}

impl Objective for PotObjective<'_> {
    fn value(&self, problem: &Problem, trial: &Trial, shot: &Shot) -> Option<f64> {
        let v = self.frame.judge(shot).ok()?;
        let o = outcome(self.frame, &v, self.valuer, Some(self.pot));
        if !o.potted {
            return None;
        }
        match self.frame.next(&v) {
            Next::Play(next) if next.state().to_play == self.frame.state().to_play => {
                let gain = v.points as f64 - v.foul_points() as f64;
                let spread = match self.spread {
                    SpreadModel::AlongPath => {
                        let (path, heading) = cue_path(shot, problem.cue());
                        let sd = self.valuer.noise.speed;
                        Spread::along_path(trial.cue.speed, sd, path, heading)
                    }
                    SpreadModel::Sensitivities => Spread::from_shifts(&end_shifts(
                        self.frame,
                        &trial.cue,
                        trial.cue_final,
                        &self.valuer.noise,
                    )),
                };
                Some(gain + self.valuer.robust(&next, &spread))
            }
            _ => Some(o.value),
        }
    }
}

/// What a miss is guessed to cost when candidates are ranked before their noise samples, as a
/// share of the rest of the frame's break ([`Valuer::future`]): the opponent's chances from
/// wherever the balls stop.
pub const MISS_SHARE: f64 = 0.3;

/// A grid of strokes: every combination of the cue speeds, the heights and the sides (shares
/// of the bounds' reach).
fn grid(frame: &Frame, speeds: &[f64], heights: &[f64], sides: &[f64]) -> Vec<Stroke> {
    let b = candidates::bounds(frame);
    let reach = b.height.hi;
    let mut out = Vec::new();
    for &speed in speeds {
        for &h in heights {
            for &side in sides {
                out.push(Stroke {
                    speed,
                    side: side * reach,
                    height: h * reach,
                    elevation: ELEVATION,
                    mouth: 0.0,
                });
            }
        }
    }
    out
}

/// Shots simulated so far by the targets' problems.
fn shots(targets: &[Target]) -> u64 {
    targets.iter().map(|t| t.problem.shots()).sum()
}

/// What the search found from one place of the cue ball.
pub(crate) struct Found {
    /// Every ball on into every pocket, as a planner problem.
    pub targets: Vec<Target>,
    /// The lines open to the targets, in order of their first estimate.
    pub lines: Vec<LineCandidate>,
    /// (line, stroke, estimated expected value), best first, each strike once.
    pub strokes: Vec<(usize, Scored, f64)>,
    /// Shots the search simulated.
    pub shots: u64,
}

/// The deterministic search from `frame` (cue ball placed) within `budget` shots.
pub(crate) fn search(frame: &Frame, valuer: &Valuer, ctx: &Context, budget: u64) -> Found {
    // The planner's problems stop at the watch's flag; their shots are counted to it after
    // each batch.
    let targets: Vec<Target> = candidates::targets(frame)
        .into_iter()
        .map(|t| Target {
            problem: t.problem.with_cancel(ctx.watch.cancel_flag().clone()),
            ..t
        })
        .collect();
    let counted = std::cell::Cell::new(0);
    let report = || {
        let now = shots(&targets);
        ctx.watch.count(now - counted.replace(now));
    };
    let lines = candidates::lines(&targets, valuer);
    // (line, stroke, estimated expected value).
    let mut found: Vec<(usize, Scored, f64)> = Vec::new();
    let miss_cost = MISS_SHARE * valuer.future(frame, 0.0);
    let run = |indices: &[usize], strokes: &[Stroke]| -> Vec<(usize, Scored, f64)> {
        let results: Vec<Vec<Scored>> = indices
            .par_iter()
            .map(|&li| {
                let lc: &LineCandidate = &lines[li];
                let t = &targets[lc.target];
                let objective = PotObjective::new(t, valuer, SpreadModel::AlongPath);
                let mut s = explore(&t.problem, &lc.line, strokes, &objective);
                // Best first; ties in the grid's order.
                s.sort_by(|a, b| b.value.total_cmp(&a.value));
                s.truncate(PER_LINE);
                s
            })
            .collect();
        indices
            .iter()
            .zip(results)
            .flat_map(|(&li, r)| {
                let c = lines[li].chance;
                r.into_iter().map(move |s| {
                    let ev = c * s.value - (1.0 - c) * miss_cost;
                    (li, s, ev)
                })
            })
            .collect()
    };
    // Coarse: every line in the order of its first estimate, while the budget lasts.
    let coarse = grid(frame, &COARSE_SPEEDS, &COARSE_HEIGHTS, &[0.0]);
    let coarse_budget = (COARSE_SHARE * budget as f64) as u64;
    let all: Vec<usize> = (0..lines.len()).collect();
    for (batch_index, batch) in all.chunks(LINE_BATCH).enumerate() {
        if batch_index > 0 && shots(&targets) >= coarse_budget {
            break;
        }
        found.extend(run(batch, &coarse));
        report();
    }
    // Fine: the lines whose coarse strokes promise most, best first, while it lasts.
    let mut best_of_line: Vec<(usize, f64)> = Vec::new();
    for (li, _, ev) in &found {
        match best_of_line.iter_mut().find(|(l, _)| l == li) {
            Some(b) => b.1 = b.1.max(*ev),
            None => best_of_line.push((*li, *ev)),
        }
    }
    best_of_line.sort_by(|a, b| b.1.total_cmp(&a.1));
    best_of_line.truncate(FINE_LINES);
    let fine = grid(frame, &FINE_SPEEDS, &FINE_HEIGHTS, &FINE_SIDES);
    let order: Vec<usize> = best_of_line.iter().map(|b| b.0).collect();
    for (batch_index, batch) in order.chunks(2).enumerate() {
        if batch_index > 0 && shots(&targets) >= budget {
            break;
        }
        found.extend(run(batch, &fine));
        report();
    }
    found.sort_by(|a, b| b.2.total_cmp(&a.2));
    // Refine: the grids' speeds are 40 % apart, the cue ball's run goes as the speed
    // squared, so the best strokes are taken on between the grid's points, valued over
    // the spread of the stroke's own sensitivities (four more simulations a point: the
    // spin's errors and the way's contacts, which the grid's closed form misses, move the
    // end as much as the speed's). A refined stroke replaces its grid point only when it
    // beats the grid's value of it (the planner's `refine`); docs/playing.md, "The
    // fourth round", measured the pair over 300 layouts.
    let top = REFINED.min(found.len());
    let refined: Vec<(Scored, f64)> = found[..top]
        .par_iter()
        .map(|(li, s, _)| {
            let lc: &LineCandidate = &lines[*li];
            let t = &targets[lc.target];
            let objective = PotObjective::new(t, valuer, SpreadModel::Sensitivities);
            let r = refine(
                &t.problem,
                &lc.line,
                s,
                &objective,
                REFINE_ITERS,
                REFINE_SIZE,
            );
            let c = lc.chance;
            let ev = c * r.value - (1.0 - c) * miss_cost;
            (r, ev)
        })
        .collect();
    for (k, (r, ev)) in refined.into_iter().enumerate() {
        found[k].1 = r;
        found[k].2 = ev;
    }
    report();
    found.sort_by(|a, b| b.2.total_cmp(&a.2));
    let shots = shots(&targets);
    if std::env::var("PLAYER_DEBUG").is_ok() {
        for lc in &lines {
            let t = &targets[lc.target];
            eprintln!(
                "line {} {} {:?} chance {:.2} est {:.2}",
                t.frame.balls()[t.ball].id,
                t.frame.table().pockets[t.pocket].name,
                lc.line.kind,
                lc.chance,
                lc.estimate
            );
        }
        for (li, s, ev) in &found {
            let t = &targets[lines[*li].target];
            eprintln!(
                "found {} {} {:?} speed {:.2} h {:.4} side {:.4} value {:.2} ev {:.2} cue_to {:.2},{:.2}",
                t.frame.balls()[t.ball].id,
                t.frame.table().pockets[t.pocket].name,
                lines[*li].line.kind,
                s.stroke.speed,
                s.stroke.height,
                s.stroke.side,
                s.value,
                ev,
                s.trial.cue_final.x,
                s.trial.cue_final.y
            );
        }
    }
    // The same strike found by both passes is sampled once.
    let mut seen: Vec<[u64; 5]> = Vec::new();
    found.retain(|(_, s, _)| {
        let c = s.trial.cue;
        let key = [
            c.speed.to_bits(),
            c.aim.to_bits(),
            c.offset[0].to_bits(),
            c.offset[1].to_bits(),
            c.elevation.to_bits(),
        ];
        let fresh = !seen.contains(&key);
        seen.push(key);
        fresh
    });
    Found {
        targets,
        lines,
        strokes: found,
        shots,
    }
}
