//! Judging a simulated stroke (formats.md, "Referee result"; WPBSA Section 3): the first ball
//! hit, the pots, the fouls in the contract's order and their value, the points, the colours
//! respotted, the end of the frame, and who plays what next (a free ball when the incoming
//! player is snookered after a foul).

use crate::colour::{self, Colour};
use crate::error::JudgeError;
use crate::foul::{self, Foul, FoulReason};
use crate::frame::Frame;
use crate::jump;
use crate::respot::{self, Respot};
use crate::snookered;
use crate::state::{FrameState, On, opponent};
use crate::verdict::Verdict;
use snooker_engine::{Ball, BallKind, BallState, Ending, EventKind, Shot, Vec3};

/// Impacts of the cue ball this close in time are simultaneous, s (formats.md).
pub const SIMULTANEOUS: f64 = 1e-9;

/// What the shot did, as the rules see it: the balls first hit, pots and balls off the table.
struct Happened {
    /// When the cue ball first met a ball.
    t_first: Option<f64>,
    first: Vec<usize>,
    potted: Vec<usize>,
    off: Vec<usize>,
}

fn happened(shot: &Shot, cue: usize) -> Happened {
    let mut first = Vec::new();
    let mut t0 = None;
    let (mut potted, mut off) = (Vec::new(), Vec::new());
    for e in &shot.events {
        match e.kind {
            EventKind::BallBall if e.balls.contains(&cue) => {
                let t = *t0.get_or_insert(e.t);
                if e.t - t <= SIMULTANEOUS
                    && let Some(&other) = e.balls.iter().find(|&&b| b != cue)
                    && !first.contains(&other)
                {
                    first.push(other);
                }
            }
            EventKind::BallPocket => potted.push(e.balls[0]),
            EventKind::BallOffTable => off.push(e.balls[0]),
            _ => {}
        }
    }
    Happened {
        t_first: t0,
        first,
        potted,
        off,
    }
}

/// True when the cue ball meets ball `ball` as the stroke starts (within [`SIMULTANEOUS`] of
/// it): for a ball it touched, the stroke moved it.
fn moved_at_start(shot: &Shot, cue: usize, ball: usize) -> bool {
    shot.events.iter().any(|e| {
        e.kind == EventKind::BallBall
            && e.t <= SIMULTANEOUS
            && e.balls.contains(&cue)
            && e.balls.contains(&ball)
    })
}

impl Frame {
    /// Judges `shot`, simulated from this frame (its balls, in order, the cue ball struck:
    /// [`Frame::setup`]), by the rules of snooker. Cheap next to the simulation: no JSON, one
    /// pass over the events, the snookered test only after a foul.
    pub fn judge(&self, shot: &Shot) -> Result<Verdict, JudgeError> {
        let cue = self.check_ready()?;
        let balls = self.balls();
        if shot.tracks.len() != balls.len()
            || shot
                .tracks
                .iter()
                .zip(balls)
                .any(|(t, b)| t.id != b.id || t.kind != b.kind)
        {
            return Err(JudgeError::ShotMismatch {
                shot: shot.tracks.iter().map(|t| t.id.clone()).collect(),
                frame: balls.iter().map(|b| b.id.clone()).collect(),
            });
        }
        if shot.ending != Ending::AtRest {
            return Err(JudgeError::NotAtRest);
        }
        let s = *self.state();
        let kind = |i: usize| balls[i].kind;
        let on = |i: usize| self.is_on(kind(i));
        let value_on = self.value_on().unwrap_or(0);
        // A free ball takes the value of the ball on (WPBSA Section 3 Rule 12).
        let value = |i: usize| {
            if s.free_ball && s.nominated.is_some_and(|n| n.kind() == kind(i)) {
                value_on
            } else {
                colour::value(kind(i))
            }
        };
        let h = happened(shot, cue);
        let cue_potted = h.potted.contains(&cue);
        let potted: Vec<usize> = h.potted.iter().copied().filter(|&i| i != cue).collect();
        let (potted_on, potted_not_on): (Vec<usize>, Vec<usize>) =
            potted.iter().partition(|&&i| on(i));

        // Touching ball (Section 3 Rule 8): a ball the cue ball touches as it lies must not be
        // moved by the stroke, or it is a push stroke (8(b)); one that is on, not moved, counts
        // as hit, so playing away from it is no foul whatever the cue ball meets next (8(c)).
        let touching = self.touching();
        let pushed = touching.iter().any(|&i| moved_at_start(shot, cue, i));
        // With a free ball nominated, only it may be the ball deemed hit (Rule 12(c)(i)).
        let free = self.free_ball_nominated();
        let deemed_hit = !pushed
            && touching
                .iter()
                .any(|&i| free.map_or(on(i), |k| kind(i) == k));

        // Fouls, in the contract's order.
        let mut reasons = Vec::new();
        // With a free ball nominated, the cue ball must meet it first, alone or at the same
        // instant as the ball on (WPBSA Section 3 Rule 12(c)(i)).
        let free_missed = free.is_some_and(|free| !h.first.iter().any(|&i| kind(i) == free));
        let first_not_on = free_missed || h.first.iter().any(|&i| !on(i));
        if deemed_hit {
            // Played away from a touching ball on: it was the ball hit.
        } else if h.first.is_empty() {
            reasons.push(FoulReason::NoBallHit);
        } else if first_not_on {
            reasons.push(FoulReason::FirstHitNotOn);
        }
        let colour_on = s.on != On::Red;
        let reds_not_on = potted_not_on.iter().any(|&i| kind(i) == BallKind::Red);
        if (!colour_on && !potted_not_on.is_empty()) || (colour_on && reds_not_on) {
            reasons.push(FoulReason::BallNotOnPotted);
        }
        if cue_potted {
            reasons.push(FoulReason::CueBallPotted);
        }
        if !h.off.is_empty() {
            reasons.push(FoulReason::OffTable);
        }
        let wrong_colours = potted_not_on.iter().any(|&i| Colour::of(kind(i)).is_some());
        if colour_on && wrong_colours {
            reasons.push(if potted_on.is_empty() {
                FoulReason::WrongColourPotted
            } else {
                FoulReason::TwoColoursPotted
            });
        }
        let finals = shot.final_states();
        if self.snookered_by_free_ball(&finals, cue) {
            reasons.push(FoulReason::SnookeredByFreeBall);
        }
        if pushed {
            reasons.push(FoulReason::PushStroke);
        }
        if jump::jump_shot(shot, cue, h.t_first.map(|t| (t, h.first.as_slice()))) {
            reasons.push(FoulReason::JumpShot);
        }
        let foul = reasons.first().map(|&reason| Foul {
            reason,
            points: foul::value(
                std::iter::once(value_on)
                    .chain(h.first.iter().map(|&i| value(i)))
                    .chain(potted.iter().map(|&i| value(i)))
                    .chain(h.off.iter().filter(|&&i| i != cue).map(|&i| value(i))),
            ),
            reasons: reasons.clone(),
        });

        // Points: each red (and a free ball played as a red) 1; the colour on its value; a
        // free ball the value of the ball on, scored once with the ball on (Rule 12).
        let points = match (&foul, s.on) {
            (Some(_), _) => 0,
            (None, On::Red) => potted_on.len() as u32,
            (None, _) if potted_on.is_empty() => 0,
            (None, _) => value_on,
        };
        // Saturating: a file may give scores near the integers' end.
        let mut scores = s.scores;
        let me = s.to_play as usize;
        scores[me] = scores[me].saturating_add(points);
        if let Some(f) = &foul {
            let other = opponent(s.to_play) as usize;
            scores[other] = scores[other].saturating_add(f.points);
        }

        // Where the balls are: at rest on the table, or out of play.
        let r = self.params().ball_radius;
        let in_play = |i: usize| finals[i].motion.in_play();
        // Colours back on their spots (Section 3 Rule 7): off the table always; potted in a
        // foul, or while reds remain or after the last red (on = red with a free ball, on =
        // colour), or as a free ball; a closing colour potted legally stays down.
        let respot_colour = |i: usize| match Colour::of(kind(i)) {
            None => false,
            Some(c) => {
                h.off.contains(&i)
                    || (potted.contains(&i)
                        && (foul.is_some()
                            || match s.on {
                                On::Red | On::Colour => true,
                                On::Closing(on) => on != c,
                            }))
            }
        };
        let mut to_respot: Vec<usize> = (0..balls.len()).filter(|&i| respot_colour(i)).collect();
        let mut cue_in_hand = cue_potted || h.off.contains(&cue);

        // End of frame (Section 3 Rule 4): with only the black left, the first score or foul.
        let last_black = s.on == On::Closing(Colour::Black);
        let over = last_black && (foul.is_some() || points > 0);
        let mut next = None;
        let mut winner = None;
        if over && scores[0] != scores[1] {
            winner = Some(if scores[0] > scores[1] { 0 } else { 1 });
        } else if over {
            // Equal scores: the black is respotted, and the first player plays it from hand
            // (the rules draw lots; we fix it: formats.md).
            to_respot = (0..balls.len())
                .filter(|&i| kind(i) == BallKind::Black)
                .collect();
            cue_in_hand = true;
            next = Some(FrameState {
                on: On::Closing(Colour::Black),
                nominated: None,
                scores,
                to_play: s.first_player,
                ball_in_hand: true,
                first_player: s.first_player,
                free_ball: false,
            });
        }

        // The table after the stroke, then the respotted colours.
        let stays = |i: usize| in_play(i) && !to_respot.contains(&i) && !(i == cue && cue_in_hand);
        let on_table: Vec<Vec3> = (0..balls.len())
            .filter(|&i| stays(i))
            .map(|i| finals[i].pos)
            .collect();
        let colours: Vec<Colour> = to_respot
            .iter()
            .filter_map(|&i| Colour::of(kind(i)))
            .collect();
        let respots: Vec<Respot> = if winner.is_some() {
            Vec::new()
        } else {
            respot::respot(&colours, &on_table, self.dims(), self.params())
                .map_err(JudgeError::NoRoomToSpot)?
        };
        let respotted_at = |i: usize| {
            Colour::of(kind(i))
                .filter(|_| to_respot.contains(&i))
                .and_then(|c| respots.iter().find(|p| p.colour == c))
        };
        let next_balls: Vec<Ball> = if winner.is_some() {
            Vec::new()
        } else {
            (0..balls.len())
                .filter_map(|i| {
                    let pos = match respotted_at(i) {
                        Some(p) => p.pos,
                        None if stays(i) => finals[i].pos,
                        None => return None,
                    };
                    Some(Ball {
                        id: balls[i].id.clone(),
                        kind: kind(i),
                        state: BallState::at_rest(pos.x, pos.y, r),
                    })
                })
                .collect()
        };

        if !over {
            let reds_left = next_balls
                .iter()
                .filter(|b| b.kind == BallKind::Red)
                .count();
            let lowest = || {
                Colour::ALL
                    .into_iter()
                    .find(|&c| next_balls.iter().any(|b| b.kind == c.kind()))
                    .unwrap_or(Colour::Black)
            };
            let visit_goes_on = foul.is_none() && points > 0;
            let (to_play, on) = if visit_goes_on {
                let on = match s.on {
                    On::Red => On::Colour,
                    On::Colour if reds_left > 0 => On::Red,
                    On::Colour => On::Closing(lowest()),
                    On::Closing(c) if potted_on.iter().any(|&i| kind(i) == c.kind()) => {
                        On::Closing(c.next().unwrap_or(Colour::Black))
                    }
                    On::Closing(c) => On::Closing(c),
                };
                (s.to_play, on)
            } else if reds_left > 0 {
                (opponent(s.to_play), On::Red)
            } else {
                (opponent(s.to_play), On::Closing(lowest()))
            };
            let free_ball = foul.is_some() && self.snookered_after(&next_balls, on, cue_in_hand);
            next = Some(FrameState {
                on,
                nominated: None,
                scores,
                to_play,
                ball_in_hand: cue_in_hand,
                first_player: s.first_player,
                free_ball,
            });
        }

        let id = |i: usize| balls[i].id.clone();
        let first_hit = h
            .first
            .iter()
            .find(|&&i| !on(i))
            .or(h.first.first())
            .map(|&i| id(i));
        let respotted = respots
            .iter()
            .filter_map(|p| {
                to_respot
                    .iter()
                    .find(|&&i| Colour::of(kind(i)) == Some(p.colour))
                    .map(|&i| (id(i), *p))
            })
            .collect();
        Ok(Verdict {
            foul,
            first_hit,
            potted: potted.iter().map(|&i| id(i)).collect(),
            cue_ball_potted: cue_potted,
            off_table: h.off.iter().map(|&i| id(i)).collect(),
            points,
            scores,
            next,
            respotted,
            winner,
            balls: next_balls,
        })
    }

    /// True when a free ball stroke leaves the cue ball snookered on every ball on by the free
    /// ball (WPBSA Section 3 Rule 12(b)(ii)), except with only the pink and black left as object
    /// balls. "By the free ball": it is the effective snookering ball, the nearest of the balls
    /// in the way to the cue ball, and with reds on the same for every red (`snookered::
    /// effective_snookering`). Judged on the balls as they lie: a free ball potted is spotted by
    /// the rules, not left by the striker; a cue ball potted or forced off is in hand; no ball
    /// on left on the table, nothing to be snookered on.
    fn snookered_by_free_ball(&self, finals: &[BallState], cue: usize) -> bool {
        let Some(free) = self.free_ball_nominated() else {
            return false;
        };
        let balls = self.balls();
        let pink_and_black_only = balls
            .iter()
            .filter(|b| b.kind != BallKind::Cue)
            .all(|b| matches!(b.kind, BallKind::Pink | BallKind::Black));
        if pink_and_black_only || !finals[cue].motion.in_play() {
            return false;
        }
        let (mut on, mut others, mut free_at) = (Vec::new(), Vec::new(), None);
        for (i, b) in balls.iter().enumerate() {
            if i == cue || !finals[i].motion.in_play() {
                continue;
            }
            let pos = finals[i].pos;
            if b.kind == free {
                free_at = Some(others.len());
                others.push(pos);
            } else if self.is_on(b.kind) {
                on.push(pos);
            } else {
                others.push(pos);
            }
        }
        let r = self.params().ball_radius;
        free_at.is_some_and(|k| {
            let curved = snookered::curved_faces(self.table(), self.params());
            snookered::effective_snookering(finals[cue].pos, &on, &others, &curved, r).contains(&k)
        })
    }

    /// True when the incoming player, on `on` with `balls` on the table, is snookered (WPBSA
    /// Section 3 Rule 12): from where the cue ball lies, or from every position in the D when
    /// it is in hand.
    fn snookered_after(&self, balls: &[Ball], on: On, in_hand: bool) -> bool {
        let is_on = |k: BallKind| match on {
            On::Red => k == BallKind::Red,
            On::Colour => Colour::of(k).is_some(),
            On::Closing(c) => k == c.kind(),
        };
        let (mut on_pos, mut not_on) = (Vec::new(), Vec::new());
        let mut cue = None;
        for b in balls {
            match b.kind {
                BallKind::Cue => cue = Some(b.state.pos),
                k if is_on(k) => on_pos.push(b.state.pos),
                _ => not_on.push(b.state.pos),
            }
        }
        let r = self.params().ball_radius;
        let curved = snookered::curved_faces(self.table(), self.params());
        match cue {
            Some(c) if !in_hand => snookered::is_snookered(c, &on_pos, &not_on, &curved, r),
            _ => snookered::is_snookered_in_hand(&self.the_d(), &on_pos, &not_on, &curved, r),
        }
    }
}
