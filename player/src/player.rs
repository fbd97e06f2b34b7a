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
//! strokes (`search.rs`: lines in order of their first estimate, a grid of speeds and heights
//! on each, the heading solved by the planner) until [`DETERMINISTIC_SHARE`] of it is spent,
//! the best few strokes then refined between the grid's points (Nelder–Mead, the planner's
//! `refine`); the noise samples of the best candidates with the rest (`sampling.rs`).
//! Safeties are in `safety.rs`, the cue ball's place in hand in `placement.rs`; this module
//! puts them together. Everything is simulated in parallel and reduced in a fixed order;
//! every random draw is seeded from (seed, stroke, placement, candidate, sample), so the
//! decision is the same on any machine and thread count.

use crate::agent::{Agent, ChooseError, Context};
use crate::candidates;
use crate::decision::{Considered, Decision, PlanKind};
use crate::placement::placements;
use crate::safety::safeties;
use crate::sampling::{MIN_SAMPLES, allotment, sample};
use crate::search::{Found, search};
use crate::value::Valuer;
use snooker_engine::Cue;
use snooker_planner::Scored;
use snooker_rules::Frame;

pub use crate::search::MISS_SHARE;

/// Share of the effort spent on the deterministic search (the rest on noise samples).
pub const DETERMINISTIC_SHARE: f64 = 0.75;
/// Below this expected value (points) of the best pot, safeties are considered too.
pub const SAFETY_BELOW: f64 = 1.0;

/// The player.
#[derive(Debug, Clone, Copy, Default)]
pub struct Player;

/// A frame to play from: the cue ball where it lies, or placed in hand.
pub(crate) struct Place<'a> {
    /// The frame, the cue ball placed.
    pub frame: &'a Frame,
    /// Where it was placed in hand.
    pub placement: Option<[f64; 2]>,
    /// Its number among the places tried (in the seeding of the noise samples).
    pub index: u64,
}

/// A stroke evaluated under noise.
#[derive(Debug, Clone)]
pub(crate) struct Evaluated {
    /// Where the cue ball in hand was placed for it.
    pub placement: Option<[f64; 2]>,
    /// The colour nominated with it.
    pub nominated: Option<snooker_rules::Colour>,
    /// The strike meant.
    pub strike: Cue,
    /// What the log shows of it.
    pub considered: Considered,
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
        let (placement, place_index) = (place.placement, place.index);
        let Found {
            targets,
            lines,
            strokes: found,
            shots: mut used,
        } = search(place.frame, valuer, ctx, budget);
        let (k, n) = allotment(samples_budget, found.len());
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
                        ball: t.first_ball(&lc.line),
                        pot: pot_id,
                        pocket: t.frame.table().pockets[t.pocket].name.clone(),
                        kind: PlanKind::from(lc.line.kind),
                        via: t.via(&lc.line),
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
                let (e, n) = safeties(place, &valuer, ctx, samples_budget);
                all.extend(e);
                used += n;
            }
        }
        if all.is_empty() {
            // Nothing potted, played safe, away or escaped legally without noise (every
            // stroke tried fouls): the nearest ball on, full.
            let f = &frames[0];
            let (strike, b) = crate::greedy::nearest_full(f).ok_or(ChooseError::NoStrike)?;
            let kind = f.balls()[b].kind;
            let nominated = candidates::nomination(f, kind);
            let g = f.with_nomination(nominated)?;
            let (value, _, sims) = sample(&g, &strike, &valuer, None, ctx, [0, 2, 0], MIN_SAMPLES);
            used += sims + 1;
            ctx.watch.count(1);
            // Where the cue ball stops played without noise, as every safety's target.
            let played = g.play(&strike).map_err(|_| ChooseError::NoStrike)?;
            let cue = g.cue_index().map_or([0.0; 2], |i| {
                let p = played.shot.final_states()[i].pos;
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
