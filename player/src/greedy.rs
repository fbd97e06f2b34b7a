//! The greedy baseline: the stroke with the highest pot probability, with no position play and
//! no safety. Every open line of every ball on (as the player finds them) is aimed with one
//! plain stroke (centre ball, a medium pace) and sampled under the noise; the likeliest pot is
//! played whatever it leaves. With no line open it strikes the nearest ball on full. The cue
//! ball in hand goes where the likeliest pot is (its chance in closed form).

use crate::agent::{Agent, ChooseError, Context};
use crate::candidates::{self, ELEVATION};
use crate::decision::{Considered, Decision, PlanKind};
use crate::outcome::outcome;
use crate::value::Valuer;
use rayon::prelude::*;
use snooker_engine::{BallKind, Cue};
use snooker_planner::{Stroke, rng_for};
use snooker_rules::Frame;

/// The one stroke greedy plays at every line: centre ball at this cue speed, m/s.
pub const SPEED: f64 = 1.5;
/// Lines aimed at most (the best first estimates).
const LINES: usize = 12;

/// The greedy baseline.
#[derive(Debug, Clone, Copy, Default)]
pub struct Greedy;

/// The nearest ball on struck full at [`SPEED`]: a legal stroke when nothing can be potted.
pub fn nearest_full(frame: &Frame) -> Option<(Cue, usize)> {
    let cue = frame.cue_index()?;
    let c = frame.balls()[cue].state.pos;
    let b = frame.balls_on().into_iter().min_by(|&a, &b| {
        let d = |i: usize| (frame.balls()[i].state.pos - c).xy().norm();
        d(a).total_cmp(&d(b))
    })?;
    let to = frame.balls()[b].state.pos - c;
    Some((
        Cue {
            speed: SPEED,
            aim: to.y.atan2(to.x),
            offset: [0.0, 0.0],
            elevation: ELEVATION,
        },
        b,
    ))
}

impl Agent for Greedy {
    fn name(&self) -> &'static str {
        "greedy"
    }

    fn choose(&self, frame: &Frame, ctx: &Context) -> Result<Decision, ChooseError> {
        let valuer = Valuer::new(&ctx.noise, frame.params());
        let placement = if frame.state().ball_in_hand {
            let (_, at) = valuer.best_in_hand(frame);
            Some(at.ok_or(ChooseError::NoStrike)?)
        } else {
            None
        };
        let f = match placement {
            Some(at) => frame.with_cue_ball_at(at)?,
            None => frame.clone(),
        };
        let targets = candidates::targets(&f);
        let lines = candidates::lines(&targets, &valuer);
        let stroke = Stroke {
            speed: SPEED,
            side: 0.0,
            height: 0.0,
            elevation: ELEVATION,
            mouth: 0.0,
        };
        let aimed: Vec<_> = lines[..lines.len().min(LINES)]
            .par_iter()
            .map(|lc| {
                let t = &targets[lc.target];
                t.problem.aimed(&stroke, &lc.line).map(|tr| (lc, tr))
            })
            .collect::<Vec<_>>()
            .into_iter()
            .flatten()
            .collect();
        let mut shots: u64 = targets.iter().map(|t| t.problem.shots()).sum();
        let n = ((ctx.effort as usize) / aimed.len().max(1)).clamp(8, 64);
        let cue = f.cue_index().ok_or(ChooseError::NoStrike)?;
        let ball = f.balls()[cue].state;
        let mut best: Option<(f64, Considered, Cue, Option<snooker_rules::Colour>)> = None;
        for (c, (lc, trial)) in aimed.iter().enumerate() {
            let t = &targets[lc.target];
            let pot = t.frame.balls()[t.ball].id.clone();
            let results: Vec<Option<bool>> = (0..n as u64)
                .into_par_iter()
                .map(|k| {
                    let mut rng = rng_for(ctx.seed, &[ctx.stroke, 0, 0, c as u64, k]);
                    let executed = ctx.noise.apply(&trial.cue, &ball, f.params(), &mut rng);
                    let s = t.frame.play(&executed).ok()?;
                    Some(outcome(&t.frame, &s.verdict, &valuer, Some(&pot)).potted)
                })
                .collect();
            shots += n as u64;
            let p = results.iter().filter(|r| **r == Some(true)).count() as f64 / n as f64;
            if best.as_ref().is_none_or(|b| p > b.0) {
                best = Some((
                    p,
                    Considered {
                        ball: t.first_ball(&lc.line),
                        pot,
                        pocket: t.frame.table().pockets[t.pocket].name.clone(),
                        kind: PlanKind::from(lc.line.kind),
                        via: t.via(&lc.line),
                        pot_probability: p,
                        cue_to: [trial.cue_final.x, trial.cue_final.y],
                        value: p,
                        samples: n,
                    },
                    trial.cue,
                    t.nominated,
                ));
            }
        }
        let (strike, plan, nominated) = match best {
            Some((_, plan, strike, nominated)) => (strike, plan, nominated),
            None => {
                let (strike, b) = nearest_full(&f).ok_or(ChooseError::NoStrike)?;
                let kind = f.balls()[b].kind;
                let plan = Considered {
                    pot: String::new(),
                    ball: f.balls()[b].id.clone(),
                    pocket: String::new(),
                    kind: PlanKind::Safety,
                    via: Vec::new(),
                    pot_probability: 0.0,
                    cue_to: [ball.pos.x, ball.pos.y],
                    value: 0.0,
                    samples: 0,
                };
                debug_assert!(kind != BallKind::Cue);
                (strike, plan, candidates::nomination(&f, kind))
            }
        };
        Ok(Decision {
            placement,
            nominated,
            strike,
            plan,
            alternatives: Vec::new(),
            shots,
        })
    }
}
