//! Safeties (step 6 of docs/playing.md, "How a stroke is chosen"): when no pot is worth its
//! risk, the nearest balls on struck full, half and thin, valued by what they leave the
//! opponent; from a ball on the cue ball touches, strokes played away from it (WPBSA Section
//! 3 Rule 8(c): it counts as hit); snookered (no such stroke legal played without noise),
//! escapes off one cushion, then two, aimed at the ball's mirror images in the cushions'
//! centre lines (the planner's doubles' geometry, `planner/src/line.rs`) over a window of
//! aims wide enough for the real rebound angles, which the engine then decides.

use crate::agent::Context;
use crate::candidates::{self, ELEVATION};
use crate::decision::{Considered, PlanKind};
use crate::outcome::outcome;
use crate::player::{Evaluated, Place};
use crate::sampling::{MIN_CANDIDATES, MIN_SAMPLES, sample};
use crate::value::Valuer;
use rayon::prelude::*;
use snooker_engine::{Cue, Vec3};
use snooker_rules::{Colour, Frame};

/// Safety strokes: where the cue ball's path passes the ball aimed at (shares of 2R across
/// it: 0 full, ±0.9 thin), the cue speeds and heights (shares of the reach).
const SAFETY_CONTACTS: [f64; 7] = [-0.9, -0.6, -0.3, 0.0, 0.3, 0.6, 0.9];
const SAFETY_SPEEDS: [f64; 4] = [0.5, 0.9, 1.6, 2.8];
const SAFETY_HEIGHTS: [f64; 2] = [0.0, -0.5];
/// Balls on aimed at for safeties (the nearest).
const SAFETY_BALLS: usize = 6;
/// Directions played away from a touching ball, rad from straight away from it.
const AWAY_TURNS: [f64; 7] = [-1.2, -0.8, -0.4, 0.0, 0.4, 0.8, 1.2];
/// Escapes: where the path passes the ball's image (shares of 2R across it). Wider than a
/// direct safety's: a cushion's rebound angle is not the mirror's (the cloth's friction, the
/// ball's spin, the nose above its centre: thesis §5), so the window must hold the real one.
const ESCAPE_CONTACTS: [f64; 13] = [
    -2.4, -2.0, -1.6, -1.2, -0.8, -0.4, 0.0, 0.4, 0.8, 1.2, 1.6, 2.0, 2.4,
];
const ESCAPE_SPEEDS: [f64; 3] = [1.0, 1.8, 2.8];
/// How close to a nose's ends an escape may meet it (m): nearer, it meets the jaw.
const NOSE_MARGIN: f64 = 0.06;

/// A safety stroke to judge: the ball it is played off (or away from), the colour nominated,
/// the frame it is played from (the nomination made), the strike, and the cushions it goes by.
struct Job {
    ball: usize,
    nominated: Option<Colour>,
    frame: Frame,
    strike: Cue,
    via: Vec<String>,
}

/// Safeties from `frame` (cue ball placed): the nearest balls on struck full, half and thin
/// at a few speeds, and strokes away from a touching ball on, judged without noise; escapes
/// off one cushion, then two, when none of those is legal; the best sampled under noise.
pub(crate) fn safeties(
    place: &Place,
    valuer: &Valuer,
    ctx: &Context,
    samples_budget: u64,
) -> (Vec<Evaluated>, u64) {
    let frame = place.frame;
    let Some(cue) = frame.cue_index() else {
        return (Vec::new(), 0);
    };
    let balls = frame.balls();
    let c = balls[cue].state.pos;
    let mut on = frame.balls_on();
    on.sort_by(|&a, &b| {
        let d = |i: usize| (balls[i].state.pos - c).xy().norm();
        d(a).total_cmp(&d(b))
    });
    on.truncate(SAFETY_BALLS);
    let mut jobs = direct(frame, &on);
    jobs.extend(away(frame));
    let mut used = 0;
    for cushions in [0, 1, 2] {
        if cushions > 0 {
            jobs = escapes(frame, &on, cushions);
        }
        let (scored, n) = judge(&jobs, valuer, ctx);
        used += n;
        if !scored.is_empty() {
            let (evaluated, n) = sampled(place, &jobs, &scored, valuer, ctx, samples_budget);
            return (evaluated, used + n);
        }
    }
    (Vec::new(), used)
}

/// The frame with the nomination a stroke at ball `b` needs, if it can be made.
fn nominated_for(frame: &Frame, b: usize) -> Option<(Option<Colour>, Frame)> {
    let nominated = candidates::nomination(frame, frame.balls()[b].kind);
    Some((nominated, frame.with_nomination(nominated).ok()?))
}

/// A plain strike along `aim` at `speed`, the cue tip `height` of its reach above centre.
fn strike(frame: &Frame, aim: f64, speed: f64, height: f64) -> Cue {
    let reach = candidates::bounds(frame).height.hi;
    Cue {
        speed,
        aim,
        offset: [0.0, height * reach],
        elevation: ELEVATION,
    }
}

/// The aim from `from` that passes `to` `across` shares of 2R to its side.
fn aim_past(frame: &Frame, from: Vec3, to: Vec3, across: f64) -> f64 {
    let d = to - from;
    let r = frame.params().ball_radius;
    let off = (across * 2.0 * r / d.xy().norm()).clamp(-1.0, 1.0).asin();
    d.y.atan2(d.x) + off
}

/// Safeties off ball `b` along `aim` from `f` (the nomination made) at every safety speed and
/// height, added to `jobs`.
fn plain(jobs: &mut Vec<Job>, b: usize, nominated: Option<Colour>, f: &Frame, aim: f64) {
    for &speed in &SAFETY_SPEEDS {
        for &h in &SAFETY_HEIGHTS {
            jobs.push(Job {
                ball: b,
                nominated,
                frame: f.clone(),
                strike: strike(f, aim, speed, h),
                via: Vec::new(),
            });
        }
    }
}

/// The balls on in `on` struck directly, full, half and thin.
fn direct(frame: &Frame, on: &[usize]) -> Vec<Job> {
    let Some(cue) = frame.cue_index() else {
        return Vec::new();
    };
    let c = frame.balls()[cue].state.pos;
    let mut jobs = Vec::new();
    for &b in on {
        let Some((nominated, f)) = nominated_for(frame, b) else {
            continue;
        };
        let o = frame.balls()[b].state.pos;
        for &across in &SAFETY_CONTACTS {
            plain(&mut jobs, b, nominated, &f, aim_past(frame, c, o, across));
        }
    }
    jobs
}

/// Strokes played away from each ball on the cue ball touches (none when it touches none).
fn away(frame: &Frame) -> Vec<Job> {
    let Some(cue) = frame.cue_index() else {
        return Vec::new();
    };
    let c = frame.balls()[cue].state.pos;
    let on = frame.balls_on();
    let mut jobs = Vec::new();
    for b in frame.touching().into_iter().filter(|b| on.contains(b)) {
        let Some((nominated, f)) = nominated_for(frame, b) else {
            continue;
        };
        let from = c - frame.balls()[b].state.pos;
        let straight_away = from.y.atan2(from.x);
        for &turn in &AWAY_TURNS {
            plain(&mut jobs, b, nominated, &f, straight_away + turn);
        }
    }
    jobs
}

/// The straight noses (not the pockets' facings): index, a point on the line a touching
/// ball's centre runs along, the unit normal into the table.
fn noses(frame: &Frame) -> Vec<(usize, Vec3, Vec3)> {
    let d = frame.params().cushion_contact_distance();
    let cushions = &frame.table().cushions;
    (0..cushions.len())
        .filter(|&k| !cushions[k].name.contains("facing"))
        .map(|k| {
            (
                k,
                cushions[k].start + d * cushions[k].normal,
                cushions[k].normal,
            )
        })
        .collect()
}

/// Whether the path from `a` towards `b` meets nose `k`'s centre line (point `p`, normal
/// `n`) head on within the nose, away from its jaws; where.
fn meets(frame: &Frame, k: usize, p: Vec3, n: Vec3, a: Vec3, b: Vec3) -> Option<Vec3> {
    let (da, db) = ((a - p).dot(&n), (b - p).dot(&n));
    if da <= 0.0 || db >= 0.0 {
        return None;
    }
    let hit = a + (da / (da - db)) * (b - a);
    let cushion = &frame.table().cushions[k];
    let along = (hit - cushion.start).dot(&cushion.direction());
    (along > NOSE_MARGIN && along < cushion.length() - NOSE_MARGIN).then_some(hit)
}

/// Escapes off `cushions` (1 or 2) cushions to the balls on in `on`: aimed at each ball's
/// image in the noses' centre lines, over [`ESCAPE_CONTACTS`], where the mirror path meets
/// each nose within it.
fn escapes(frame: &Frame, on: &[usize], cushions: usize) -> Vec<Job> {
    let Some(cue) = frame.cue_index() else {
        return Vec::new();
    };
    let c = frame.balls()[cue].state.pos;
    let c = Vec3::new(c.x, c.y, 0.0);
    let noses = noses(frame);
    let mirror = |q: Vec3, (_, p, n): (usize, Vec3, Vec3)| q - 2.0 * (q - p).dot(&n) * n;
    let routes: Vec<Vec<(usize, Vec3, Vec3)>> = match cushions {
        1 => noses.iter().map(|&x| vec![x]).collect(),
        _ => noses
            .iter()
            .flat_map(|&x| {
                noses
                    .iter()
                    .filter(move |y| y.0 != x.0)
                    .map(move |&y| vec![x, y])
            })
            .collect(),
    };
    let mut jobs = Vec::new();
    for &b in on {
        let Some((nominated, f)) = nominated_for(frame, b) else {
            continue;
        };
        let o = frame.balls()[b].state.pos;
        let o = Vec3::new(o.x, o.y, 0.0);
        for route in &routes {
            // The image seen past every cushion; then each leg must meet its nose.
            let image = route.iter().rev().fold(o, |q, &x| mirror(q, x));
            let mut from = c;
            let mut fits = true;
            for (k, &x) in route.iter().enumerate() {
                let towards = route[k..].iter().rev().fold(o, |q, &y| mirror(q, y));
                match meets(frame, x.0, x.1, x.2, from, towards) {
                    Some(hit) => from = hit,
                    None => {
                        fits = false;
                        break;
                    }
                }
            }
            if !fits {
                continue;
            }
            let via: Vec<String> = route
                .iter()
                .map(|x| frame.table().cushions[x.0].name.clone())
                .collect();
            for &across in &ESCAPE_CONTACTS {
                let aim = aim_past(frame, c, image, across);
                for &speed in &ESCAPE_SPEEDS {
                    jobs.push(Job {
                        ball: b,
                        nominated,
                        frame: f.clone(),
                        strike: strike(frame, aim, speed, 0.0),
                        via: via.clone(),
                    });
                }
            }
        }
    }
    jobs
}

/// The legal strokes of `jobs` played without noise: (job, value, where the cue ball stops),
/// best first (ties in the order of `jobs`), and the shots simulated.
fn judge(jobs: &[Job], valuer: &Valuer, ctx: &Context) -> (Vec<(usize, f64, [f64; 2])>, u64) {
    let mut scored: Vec<(usize, f64, [f64; 2])> = jobs
        .par_iter()
        .enumerate()
        .filter_map(|(k, job)| {
            if ctx.watch.is_cancelled() {
                return None;
            }
            ctx.watch.count(1);
            let f = &job.frame;
            let s = f.play(&job.strike).ok()?;
            s.verdict.legal().then_some(())?;
            let o = outcome(f, &s.verdict, valuer, None);
            let cue_end = s.shot.final_states()[f.cue_index()?].pos;
            Some((k, o.value, [cue_end.x, cue_end.y]))
        })
        .collect();
    scored.sort_by(|a, b| b.1.total_cmp(&a.1));
    (scored, jobs.len() as u64)
}

/// The best of the `scored` jobs sampled under noise within `samples_budget`.
fn sampled(
    place: &Place,
    jobs: &[Job],
    scored: &[(usize, f64, [f64; 2])],
    valuer: &Valuer,
    ctx: &Context,
    samples_budget: u64,
) -> (Vec<Evaluated>, u64) {
    let balls = place.frame.balls();
    let k = MIN_CANDIDATES.min(scored.len());
    let n = (samples_budget as usize)
        .checked_div(k)
        .map_or(0, |n| n.max(MIN_SAMPLES));
    let mut used = 0;
    let evaluated = scored
        .iter()
        .take(k)
        .enumerate()
        .map(|(i, &(j, _, cue_to))| {
            let job = &jobs[j];
            let coords = [place.index, 1, i as u64];
            let (value, _, sims) = sample(&job.frame, &job.strike, valuer, None, ctx, coords, n);
            used += sims;
            Evaluated {
                placement: place.placement,
                nominated: job.nominated,
                strike: job.strike,
                considered: Considered {
                    pot: String::new(),
                    ball: balls[job.ball].id.clone(),
                    pocket: String::new(),
                    kind: PlanKind::Safety,
                    via: job.via.clone(),
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

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    /// The rules' frame with the cue ball behind the black and the pink on beyond it.
    fn snookered() -> Frame {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../rules/tests/frames/free_ball_awarded.toml");
        snooker_rules::load(&path).unwrap().frame
    }

    /// The routes (cushions in order) of `jobs` of which some strike is legal played
    /// without noise, and all the routes.
    fn routes_reached(jobs: &[Job]) -> (usize, usize) {
        let mut routes: BTreeMap<&[String], bool> = BTreeMap::new();
        for job in jobs {
            let legal = job.frame.play(&job.strike).unwrap().verdict.legal();
            *routes.entry(&job.via).or_default() |= legal;
        }
        (routes.values().filter(|&&r| r).count(), routes.len())
    }

    #[test]
    fn the_mirror_aims_reach_the_ball_off_one_and_two_cushions() {
        let f = snookered();
        let on = f.balls_on();
        assert!(
            direct(&f, &on)
                .iter()
                .all(|j| { !j.frame.play(&j.strike).unwrap().verdict.legal() })
        );
        for cushions in [1, 2] {
            let jobs = escapes(&f, &on, cushions);
            assert!(jobs.iter().all(|j| j.via.len() == cushions));
            let (reached, routes) = routes_reached(&jobs);
            // A wrong image (a mirror in the wrong line or order) reaches almost none.
            assert!(
                reached >= 2,
                "{cushions} cushion(s): {reached} of {routes} routes reach the pink"
            );
        }
    }
}
