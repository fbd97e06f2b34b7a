//! Aiming to pot: the ghost-ball heading (the cue ball's centre sent to the point two radii
//! behind the object ball on its line to an aim point in the pocket's mouth), then corrected
//! on the engine's own result, so that throw, squirt and swerve are all allowed for (thesis
//! §7.1.5: the object ball's heading after the impact is what pots it).

use crate::problem::Problem;
use crate::trial::{Trial, angle};
use snooker_engine::Vec3;
use snooker_engine::cue::Cue;

/// Heading error at which the aim is taken as found, rad: the cue ball's end position then
/// moves by micrometres (a pot's window is ~1e-2 rad wide).
const AIM_TOLERANCE: f64 = 1e-7;
/// Most simulations of one aim correction.
const MAX_AIM_TRIALS: usize = 12;
/// Share of the mouth's half-width (less a ball's radius) the aim point may move across it.
const MOUTH_REACH: f64 = 0.8;

/// The strike variables other than the heading, and where in the pocket's mouth to aim.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stroke {
    /// Cue speed, m/s.
    pub speed: f64,
    /// Side offset, m.
    pub side: f64,
    /// Height offset, m.
    pub height: f64,
    /// Elevation, rad.
    pub elevation: f64,
    /// Aim point across the mouth, -1..1 (0: its middle).
    pub mouth: f64,
}

impl Stroke {
    /// The strike with heading `aim`.
    pub fn with_aim(&self, aim: f64) -> Cue {
        Cue {
            speed: self.speed,
            aim,
            offset: [self.side, self.height],
            elevation: self.elevation,
        }
    }
}

impl Problem {
    /// The point of the pocket's mouth a fraction `u` (-1..1) of the way across it.
    pub fn aim_point(&self, u: f64) -> Vec3 {
        let pocket = &self.setup.table.pockets[self.pocket];
        let r = self.setup.params.ball_radius;
        let inward = (pocket.centre - pocket.mouth).xy();
        let across = if inward.norm() > 0.0 {
            Vec3::new(-inward.y, inward.x, 0.0).normalize()
        } else {
            Vec3::zeros()
        };
        let half = (0.5 * pocket.mouth_width - r).max(0.0);
        pocket.mouth + MOUTH_REACH * u.clamp(-1.0, 1.0) * half * across
    }

    /// The ghost-ball heading to aim point `at`, rad, and the cut angle, rad (0 full ball).
    pub fn ghost_aim(&self, at: Vec3) -> (f64, f64) {
        let balls = &self.setup.balls;
        let (c, o) = (balls[self.cue].state.pos, balls[self.object].state.pos);
        let r = self.setup.params.ball_radius;
        let line = (at - o).xy().normalize();
        let ghost = o.xy() - 2.0 * r * line;
        let path = ghost - c.xy();
        let cut = (path.x * line.y - path.y * line.x).atan2(path.dot(&line));
        (path.y.atan2(path.x), cut)
    }

    /// The heading that sends the object ball at the stroke's aim point, found by the secant
    /// method on the engine's result from the ghost-ball heading; the trial of the best
    /// heading found (None if no heading could be struck at all).
    pub fn aimed(&self, stroke: &Stroke) -> Option<Trial> {
        let at = self.aim_point(stroke.mouth);
        let (ghost, cut) = self.ghost_aim(at);
        let r = self.setup.params.ball_radius;
        let balls = &self.setup.balls;
        let d = (balls[self.object].state.pos - balls[self.cue].state.pos)
            .xy()
            .norm();
        // A heading change moving the contact by a hundredth of a radius: the second point.
        let step = 0.01 * r * cut.cos().abs().max(0.1) / d.max(r);
        let mut best: Option<(f64, Trial)> = None;
        let mut prev: Option<(f64, f64)> = None;
        let mut aim = ghost;
        for _ in 0..MAX_AIM_TRIALS {
            let Some(t) = self.trial(&stroke.with_aim(aim)) else {
                break;
            };
            let Some((pos, vel)) = t.departure else {
                // Missed the object ball: back towards the last heading that hit it.
                match prev {
                    Some((a, _)) => aim = 0.5 * (aim + a),
                    None => break,
                }
                continue;
            };
            let e = angle(vel, at - pos);
            let better = best.as_ref().is_none_or(|(be, _)| e.abs() < be.abs());
            if better {
                best = Some((e, t));
            }
            if e.abs() < AIM_TOLERANCE {
                break;
            }
            let next = match prev {
                Some((a0, e0)) if e != e0 => aim - e * (aim - a0) / (e - e0),
                _ => aim + step,
            };
            if (next - aim).abs() < 1e-12 {
                break;
            }
            prev = Some((aim, e));
            aim = next;
        }
        best.map(|(_, t)| t)
    }
}
