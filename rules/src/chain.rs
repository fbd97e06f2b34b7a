//! Frames that chain: a frame file played after another must be the frame its stroke left
//! (formats.md: FRAME + strike -> NEXT), but for the player's own choices (the nomination,
//! and where the cue ball in hand is placed).

use crate::error::{FrameError, Key, Problem};
use crate::frame::Frame;
use snooker_engine::BallKind;

impl Frame {
    /// Checks that this frame is `expected` (the frame a stroke left, [`Frame::next`], or
    /// [`Frame::play_again`]) but for the player's choices: the nomination (nothing nominated
    /// declines a free ball: `free_ball` false where the stroke left it true, WPBSA Section 3
    /// Rule 12), and the cue ball placed when in hand. Positions must agree to the bit (a
    /// written frame reads back exactly); the name may differ.
    pub fn follows(&self, expected: &Frame) -> Result<(), FrameError> {
        let differ =
            |key: Key, what: String| Err(FrameError::new(key, Problem::DoesNotFollow(what)));
        if self.table() != expected.table() {
            return differ(Key::Other("table"), "the table differs".into());
        }
        if self.params() != expected.params() {
            return differ(Key::Other("params"), "the parameters differ".into());
        }
        if self.models() != expected.models() {
            return differ(Key::Other("models"), "the models differ".into());
        }
        if self.options() != expected.options() {
            return differ(Key::Other("sim"), "the limits of [sim] differ".into());
        }
        let (a, b) = (self.state(), expected.state());
        let fields = [
            ("on", a.on.name().to_string(), b.on.name().to_string()),
            (
                "scores",
                format!("{:?}", a.scores),
                format!("{:?}", b.scores),
            ),
            ("to_play", a.to_play.to_string(), b.to_play.to_string()),
            (
                "ball_in_hand",
                a.ball_in_hand.to_string(),
                b.ball_in_hand.to_string(),
            ),
            (
                "first_player",
                a.first_player.to_string(),
                b.first_player.to_string(),
            ),
            // A free ball may be declined (Section 3 Rule 12): false where it was awarded.
            (
                "free_ball",
                a.free_ball.to_string(),
                (b.free_ball && a.free_ball).to_string(),
            ),
        ];
        for (key, got, want) in fields {
            if got != want {
                return differ(
                    Key::Frame(key),
                    format!("{key} is {got}, the stroke left {want}"),
                );
            }
        }
        let placed = |k: BallKind| a.ball_in_hand && k == BallKind::Cue;
        for (i, ball) in self.balls().iter().enumerate() {
            if placed(ball.kind) {
                continue;
            }
            match expected.balls().iter().find(|e| e.id == ball.id) {
                None => {
                    return differ(
                        Key::Ball(i, "id"),
                        format!("ball \"{}\" is not on the table the stroke left", ball.id),
                    );
                }
                Some(e) if e.kind != ball.kind => {
                    return differ(
                        Key::Ball(i, "kind"),
                        format!("ball \"{}\" changed kind", ball.id),
                    );
                }
                Some(e) if e.state.pos.map(f64::to_bits) != ball.state.pos.map(f64::to_bits) => {
                    return differ(
                        Key::Ball(i, "pos"),
                        format!(
                            "ball \"{}\" is at ({}, {}), the stroke left it at ({}, {})",
                            ball.id,
                            ball.state.pos.x,
                            ball.state.pos.y,
                            e.state.pos.x,
                            e.state.pos.y
                        ),
                    );
                }
                Some(_) => {}
            }
        }
        if let Some(missing) = expected
            .balls()
            .iter()
            .find(|e| !self.balls().iter().any(|b| b.id == e.id))
        {
            return differ(
                Key::Other("balls"),
                format!(
                    "ball \"{}\" of the table the stroke left is missing",
                    missing.id
                ),
            );
        }
        Ok(())
    }
}
