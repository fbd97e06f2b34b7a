//! The player: for each stroke, candidate pots of every kind planned by the planner with the
//! position they leave as its objective, the best of them played many times under sampled
//! execution noise and judged by the rules, and the stroke of the highest expected value
//! chosen; a safety when no pot is worth its risk; the cue ball in hand placed where the pots
//! are best.
//!
//! The value of a stroke (points, to the player): the mean over noise samples of the points
//! scored, less foul points, plus the value of the position left to the player if they stay
//! at the table, less its value to the opponent if not ([`crate::outcome`]); a position's
//! value is the best next pot's chance times its worth ([`crate::value`]). In expectation:
//! pot probability × (points + position) − (1 − pot probability) × the opponent's chances.
//!
//! Effort (simulated shots per stroke) is shared out as: the deterministic search over
//! strokes (lines in order of their first estimate, a grid of speeds and heights on each,
//! the heading solved by the planner) until [`DETERMINISTIC_SHARE`] of it is spent, the best
//! few strokes then refined between the grid's points (Nelder–Mead, the planner's `refine`);
//! the noise samples of the best candidates with the rest. Everything is simulated in
//! parallel and reduced in a fixed order; every random draw is seeded from (seed, stroke,
//! placement, candidate, sample), so the decision is the same on any machine and thread
//! count.

use crate::agent::{Agent, ChooseError, Context};
use crate::candidates::{self, ELEVATION, LineCandidate, Target};
use crate::decision::{Considered, Decision, PlanKind};
use crate::outcome::outcome;
use crate::spread::{Spread, SpreadModel, end_shifts};
use crate::value::Valuer;
use rayon::prelude::*;
use snooker_engine::{Cue, EventKind, Shot, Vec3};
use snooker_planner::{Objective, Problem, Scored, Stroke, Trial, explore, refine, rng_for};
use snooker_rules::{Frame, Next};

/// Share of the effort spent on the deterministic search (the rest on noise samples).
pub const DETERMINISTIC_SHARE: f64 = 0.75;
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
/// Fewest and most candidates sampled under noise.
const MIN_CANDIDATES: usize = 4;
const MAX_CANDIDATES: usize = 20;
/// Fewest and most noise samples per candidate.
const MIN_SAMPLES: usize = 8;
const MAX_SAMPLES: usize = 96;
/// Below this expected value (points) of the best pot, safeties are considered too.
pub const SAFETY_BELOW: f64 = 1.0;
/// Places for the cue ball in hand tried, and how far apart (m).
const PLACEMENTS: usize = 3;
const PLACEMENT_GAP: f64 = 0.08;
/// Safety strokes: where the cue ball's path passes the ball aimed at (shares of 2R across
/// it: 0 full, ±0.9 thin), the cue speeds and heights (shares of the reach).
const SAFETY_CONTACTS: [f64; 7] = [-0.9, -0.6, -0.3, 0.0, 0.3, 0.6, 0.9];
const SAFETY_SPEEDS: [f64; 4] = [0.5, 0.9, 1.6, 2.8];
const SAFETY_HEIGHTS: [f64; 2] = [0.0, -0.5];
/// Balls on aimed at for safeties (the nearest).
const SAFETY_BALLS: usize = 6;

/// The player.
#[derive(Debug, Clone, Copy, Default)]
pub struct Player;

/// A frame to play from: the cue ball where it lies, or placed in hand.
struct Place<'a> {
    /// The frame, the cue ball placed.
    frame: &'a Frame,
    /// Where it was placed in hand.
    placement: Option<[f64; 2]>,
    /// Its number among the places tried (in the seeding of the noise samples).
    index: u64,
}

/// A stroke evaluated under noise.
#[derive(Debug, Clone)]
struct Evaluated {
    placement: Option<[f64; 2]>,
    nominated: Option<snooker_rules::Colour>,
    strike: Cue,
    considered: Considered,
}

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
                        let (path, heading) = cue_path(shot, problem.cue);
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

/// The names of what `line` goes via.
fn via(t: &Target, line: &snooker_planner::Line) -> Vec<String> {
    match line.ball {
        Some(b) => vec![t.frame.balls()[b].id.clone()],
        None => line
            .cushions
            .iter()
            .map(|&c| t.frame.table().cushions[c].name.clone())
            .collect(),
    }
}

/// Plays `strike` from `frame` under `ctx`'s noise `n` times (draws seeded from the
/// coordinates `coords` and the sample's number) and returns (mean value, pot share).
fn sample(
    frame: &Frame,
    strike: &Cue,
    valuer: &Valuer,
    pot: Option<&str>,
    ctx: &Context,
    coords: [u64; 3],
    n: usize,
) -> (f64, f64, u64) {
    let Some(cue) = frame.cue_index() else {
        return (f64::NEG_INFINITY, 0.0, 0);
    };
    let ball = frame.balls()[cue].state;
    let p = frame.params();
    let results: Vec<Option<(f64, bool)>> = (0..n as u64)
        .into_par_iter()
        .map(|k| {
            if ctx.watch.is_cancelled() {
                return None;
            }
            let mut rng = rng_for(ctx.seed, &[ctx.stroke, coords[0], coords[1], coords[2], k]);
            let executed = ctx.noise.apply(strike, &ball, p, &mut rng);
            ctx.watch.count(1);
            let stroke = frame.play(&executed).ok()?;
            let o = outcome(frame, &stroke.verdict, valuer, pot);
            Some((o.value, o.potted))
        })
        .collect();
    // A sample the engine could not simulate counts as the worst: a foul's and the
    // opponent in hand (it does not happen on a valid frame: the engine always simulates).
    let worst = -(7.0 + valuer.future(frame, 0.0));
    let total: f64 = results.iter().map(|r| r.map_or(worst, |x| x.0)).sum();
    let pots = results.iter().filter(|r| r.is_some_and(|x| x.1)).count();
    (total / n as f64, pots as f64 / n as f64, n as u64)
}

/// Places for the cue ball in hand: the best few of the D's grid by the value of the pots
/// they leave, at least [`PLACEMENT_GAP`] apart.
fn placements(frame: &Frame, valuer: &Valuer) -> Vec<[f64; 2]> {
    let r = frame.params().ball_radius;
    let others = crate::value::object_positions(frame);
    let mut scored: Vec<(f64, [f64; 2])> = frame
        .the_d()
        .grid(crate::value::IN_HAND_STEP)
        .filter(|p| others.iter().all(|o| (o - p).xy().norm() > 2.0 * r + 1e-6))
        .map(|p| (valuer.from(frame, p).0, [p.x, p.y]))
        .collect();
    // Best first; equal values keep the grid's order (its middle first).
    scored.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut out: Vec<[f64; 2]> = Vec::new();
    for (_, p) in scored {
        if out
            .iter()
            .all(|q| (p[0] - q[0]).hypot(p[1] - q[1]) >= PLACEMENT_GAP)
        {
            out.push(p);
        }
        if out.len() == PLACEMENTS {
            break;
        }
    }
    out
}

impl Player {
    /// The pots from `frame` (cue ball placed), evaluated: the deterministic search within
    /// `budget` shots, then the best candidates sampled under noise with `samples_budget`.
    fn pots(
        &self,
        place: &Place,
        valuer: &Valuer,
        ctx: &Context,
        budget: u64,
        samples_budget: u64,
    ) -> (Vec<Evaluated>, u64) {
        let (frame, placement, place_index) = (place.frame, place.placement, place.index);
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
                    let objective = PotObjective {
                        frame: &t.frame,
                        valuer,
                        pot: &t.frame.balls()[t.ball].id,
                        spread: SpreadModel::AlongPath,
                    };
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
                let objective = PotObjective {
                    frame: &t.frame,
                    valuer,
                    pot: &t.frame.balls()[t.ball].id,
                    spread: SpreadModel::Sensitivities,
                };
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
        let mut used = shots(&targets);
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
        let k = ((samples_budget / (MIN_SAMPLES as u64 * 6)) as usize)
            .clamp(MIN_CANDIDATES, MAX_CANDIDATES)
            .min(found.len());
        let n = (samples_budget as usize)
            .checked_div(k)
            .map_or(0, |n| n.clamp(MIN_SAMPLES, MAX_SAMPLES));
        let chosen: Vec<&(usize, Scored, f64)> = found.iter().take(k).collect();
        let evaluated: Vec<Evaluated> = chosen
            .iter()
            .enumerate()
            .map(|(c, (li, s, _))| {
                let lc = &lines[*li];
                let t = &targets[lc.target];
                let pot_id = t.frame.balls()[t.ball].id.clone();
                let (value, pot_probability, sims) = sample(
                    &t.frame,
                    &s.trial.cue,
                    valuer,
                    Some(&pot_id),
                    ctx,
                    [place_index, 0, c as u64],
                    n,
                );
                used += sims;
                Evaluated {
                    placement,
                    nominated: t.nominated,
                    strike: s.trial.cue,
                    considered: Considered {
                        ball: match lc.line.kind {
                            snooker_planner::ShotKind::Plant => via(t, &lc.line)
                                .first()
                                .cloned()
                                .unwrap_or_else(|| pot_id.clone()),
                            _ => pot_id.clone(),
                        },
                        pot: pot_id,
                        pocket: t.frame.table().pockets[t.pocket].name.clone(),
                        kind: PlanKind::from(lc.line.kind),
                        via: via(t, &lc.line),
                        pot_probability,
                        cue_to: [s.trial.cue_final.x, s.trial.cue_final.y],
                        value,
                        samples: n,
                    },
                }
            })
            .collect();
        (evaluated, used)
    }

    /// Safeties from `frame` (cue ball placed): the nearest balls on struck full, half and
    /// thin at a few speeds, judged without noise; the best sampled under noise.
    fn safeties(
        &self,
        place: &Place,
        valuer: &Valuer,
        ctx: &Context,
        samples_budget: u64,
    ) -> (Vec<Evaluated>, u64) {
        let (frame, placement, place_index) = (place.frame, place.placement, place.index);
        let Some(cue) = frame.cue_index() else {
            return (Vec::new(), 0);
        };
        let balls = frame.balls();
        let r = frame.params().ball_radius;
        let c = balls[cue].state.pos;
        let mut on = frame.balls_on();
        on.sort_by(|&a, &b| {
            let d = |i: usize| (balls[i].state.pos - c).xy().norm();
            d(a).total_cmp(&d(b))
        });
        on.truncate(SAFETY_BALLS);
        let reach = candidates::bounds(frame).height.hi;
        let mut jobs = Vec::new();
        for &b in &on {
            let nominated = candidates::nomination(frame, balls[b].kind);
            let Ok(f) = frame.with_nomination(nominated) else {
                continue;
            };
            let to = balls[b].state.pos - c;
            let dist = to.xy().norm();
            for &across in &SAFETY_CONTACTS {
                let off = (across * 2.0 * r / dist).clamp(-1.0, 1.0).asin();
                let aim = to.y.atan2(to.x) + off;
                for &speed in &SAFETY_SPEEDS {
                    for &h in &SAFETY_HEIGHTS {
                        let strike = Cue {
                            speed,
                            aim,
                            offset: [0.0, h * reach],
                            elevation: ELEVATION,
                        };
                        jobs.push((b, nominated, f.clone(), strike));
                    }
                }
            }
        }
        let mut scored: Vec<(usize, f64, [f64; 2])> = jobs
            .par_iter()
            .enumerate()
            .filter_map(|(k, (_, _, f, strike))| {
                if ctx.watch.is_cancelled() {
                    return None;
                }
                ctx.watch.count(1);
                let s = f.play(strike).ok()?;
                s.verdict.legal().then_some(())?;
                let o = outcome(f, &s.verdict, valuer, None);
                let cue_end = s.shot.final_states()[f.cue_index()?].pos;
                Some((k, o.value, [cue_end.x, cue_end.y]))
            })
            .collect();
        let mut used = jobs.len() as u64;
        scored.sort_by(|a, b| b.1.total_cmp(&a.1));
        let k = MIN_CANDIDATES.min(scored.len());
        let n = (samples_budget as usize)
            .checked_div(k)
            .map_or(0, |n| n.max(MIN_SAMPLES));
        let evaluated = scored
            .iter()
            .take(k)
            .enumerate()
            .map(|(i, &(j, _, cue_to))| {
                let (b, nominated, f, strike) = &jobs[j];
                let (value, _, sims) =
                    sample(f, strike, valuer, None, ctx, [place_index, 1, i as u64], n);
                used += sims;
                Evaluated {
                    placement,
                    nominated: *nominated,
                    strike: *strike,
                    considered: Considered {
                        pot: String::new(),
                        ball: balls[*b].id.clone(),
                        pocket: String::new(),
                        kind: PlanKind::Safety,
                        via: Vec::new(),
                        pot_probability: 0.0,
                        cue_to,
                        value,
                        samples: n,
                    },
                }
            })
            .collect();
        (evaluated, used)
    }
}

impl Agent for Player {
    fn name(&self) -> &'static str {
        "player"
    }

    fn choose(&self, frame: &Frame, ctx: &Context) -> Result<Decision, ChooseError> {
        let valuer = Valuer::new(&ctx.noise, frame.params());
        let in_hand = frame.state().ball_in_hand;
        let places: Vec<Option<[f64; 2]>> = if in_hand {
            placements(frame, &valuer).into_iter().map(Some).collect()
        } else {
            vec![None]
        };
        if places.is_empty() {
            return Err(ChooseError::NoStrike);
        }
        let frames: Vec<Frame> = places
            .iter()
            .map(|p| match p {
                Some(at) => frame.with_cue_ball_at(*at),
                None => Ok(frame.clone()),
            })
            .collect::<Result<_, _>>()?;
        let share = ctx.effort / places.len() as u64;
        let budget = (DETERMINISTIC_SHARE * share as f64) as u64;
        let samples_budget = share - budget;
        let mut all: Vec<Evaluated> = Vec::new();
        let mut used = 0;
        let spots: Vec<Place> = frames
            .iter()
            .zip(&places)
            .enumerate()
            .map(|(i, (frame, &placement))| Place {
                frame,
                placement,
                index: i as u64,
            })
            .collect();
        for place in &spots {
            let (e, n) = self.pots(place, &valuer, ctx, budget, samples_budget);
            all.extend(e);
            used += n;
        }
        let best_pot = all
            .iter()
            .map(|e| e.considered.value)
            .fold(f64::NEG_INFINITY, f64::max);
        if best_pot < SAFETY_BELOW {
            for place in &spots {
                let (e, n) = self.safeties(place, &valuer, ctx, samples_budget);
                all.extend(e);
                used += n;
            }
        }
        if all.is_empty() {
            // Nothing potted or played safe legally without noise: the nearest ball on, full.
            let f = &frames[0];
            let (strike, b) = crate::greedy::nearest_full(f).ok_or(ChooseError::NoStrike)?;
            let kind = f.balls()[b].kind;
            let nominated = candidates::nomination(f, kind);
            let g = f.with_nomination(nominated)?;
            let (value, _, sims) = sample(&g, &strike, &valuer, None, ctx, [0, 2, 0], MIN_SAMPLES);
            used += sims;
            let cue = f.cue_index().map_or([0.0; 2], |i| {
                let p = f.balls()[i].state.pos;
                [p.x, p.y]
            });
            all.push(Evaluated {
                placement: places[0],
                nominated,
                strike,
                considered: Considered {
                    pot: String::new(),
                    ball: f.balls()[b].id.clone(),
                    pocket: String::new(),
                    kind: PlanKind::Safety,
                    via: Vec::new(),
                    pot_probability: 0.0,
                    cue_to: cue,
                    value,
                    samples: MIN_SAMPLES,
                },
            });
        }
        if ctx.watch.is_cancelled() {
            return Err(ChooseError::Cancelled);
        }
        // Best expected value first; ties in the order considered.
        all.sort_by(|a, b| b.considered.value.total_cmp(&a.considered.value));
        let mut it = all.into_iter();
        let best = it.next().ok_or(ChooseError::NoStrike)?;
        Ok(Decision {
            placement: best.placement,
            nominated: best.nominated,
            strike: best.strike,
            plan: best.considered,
            alternatives: it.take(3).map(|e| e.considered).collect(),
            shots: used,
        })
    }
}
