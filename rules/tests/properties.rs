//! Properties over random frames and strokes: the score changes by the points scored plus the
//! foul's points, exactly; the next frame's balls are the shot's final positions with exactly
//! the respotted colours added (and it is a frame: `Frame::new` accepts it); and a frame of
//! random legal-looking strokes always ends, or reaches a cap of strokes, without an error.

use proptest::prelude::*;
use snooker_engine::{BallKind, Cue, Vec3};
use snooker_rules::{Colour, Frame, FrameState, Next, On};
use std::f64::consts::PI;

/// A random frame: an open table of `reds` reds (seeded), in one of the states its balls allow.
fn frame(reds: usize, seed: u64, pick: [u32; 6]) -> Frame {
    let base = Frame::open_table(reds, seed);
    let mut balls = base.balls().to_vec();
    let colour = |k: u32| Colour::ALL[k as usize % 6];
    let (on, nominated, free_ball) = if reds > 0 {
        match pick[0] % 4 {
            0 => (On::Red, None, false),
            1 => (On::Colour, Some(colour(pick[1])), false),
            2 => (On::Colour, None, false),
            _ => (On::Red, Some(colour(pick[1])), true),
        }
    } else if pick[0].is_multiple_of(3) {
        (On::Colour, Some(colour(pick[1])), false)
    } else {
        // The closing sequence from a random colour: the lower ones already potted.
        let c = colour(pick[2]);
        balls.retain(|b| Colour::of(b.kind).is_none_or(|k| k >= c));
        let free = pick[1].is_multiple_of(2) && c != Colour::Black;
        let nominated = free.then(|| {
            let higher: Vec<Colour> = Colour::ALL.into_iter().filter(|&k| k > c).collect();
            higher[pick[3] as usize % higher.len()]
        });
        (On::Closing(c), nominated, free)
    };
    let ball_in_hand = pick[4].is_multiple_of(3);
    if ball_in_hand {
        balls.retain(|b| b.kind != BallKind::Cue);
    }
    let state = FrameState {
        on,
        nominated,
        scores: [pick[5] % 80, pick[4] % 70],
        to_play: (pick[3] % 2) as u8,
        ball_in_hand,
        first_player: (pick[2] % 2) as u8,
        free_ball,
    };
    let f = Frame::new(
        "random",
        base.table().clone(),
        *base.params(),
        *base.models(),
        *base.options(),
        balls,
        state,
    )
    .expect("a random frame is a frame");
    if ball_in_hand {
        let d = f.the_d();
        let p = f
            .nearest_placement([d.centre.x - 0.1, d.centre.y + 0.05])
            .unwrap();
        f.with_cue_ball_at(p).unwrap()
    } else {
        f
    }
}

fn strike() -> impl Strategy<Value = Cue> {
    (
        0.3f64..7.0,
        -PI..PI,
        -0.01f64..0.01,
        -0.01f64..0.01,
        0.0f64..0.25,
    )
        .prop_map(|(speed, aim, side, height, elevation)| Cue {
            speed,
            aim,
            offset: [side, height],
            elevation,
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn scores_and_balls_follow_from_the_shot(
        reds in 0usize..=15,
        seed in any::<u64>(),
        pick in proptest::array::uniform6(any::<u32>()),
        cue in strike(),
    ) {
        let f = frame(reds, seed, pick);
        let before = *f.state();
        let stroke = match f.play(&cue) {
            Ok(s) => s,
            // A miscue or a tip through the cloth is the strike's fault, not the frame's.
            Err(snooker_rules::PlayError::Frame(e)) if e.key.to_string().starts_with("cue") => return Ok(()),
            // A colour on and nothing nominated: refused, naming the key.
            Err(snooker_rules::PlayError::Frame(e)) if before.on == On::Colour && before.nominated.is_none() => {
                prop_assert_eq!(e.key.to_string(), "frame.nominated");
                return Ok(());
            }
            Err(e) => panic!("{e}"),
        };
        let v = &stroke.verdict;
        let me = before.to_play as usize;
        // Points scored plus foul points are the score change, and go where they belong.
        prop_assert_eq!(v.scores[me], before.scores[me] + v.points);
        prop_assert_eq!(v.scores[1 - me], before.scores[1 - me] + v.foul_points());
        prop_assert!(v.foul.is_none() || v.points == 0);
        if let Some(foul) = &v.foul {
            prop_assert!((4..=7).contains(&foul.points));
        }
        // The next frame's balls: the final positions, exactly the respotted colours added.
        let finals = stroke.shot.final_states();
        let in_hand = v.next.is_some_and(|n| n.ball_in_hand);
        let respotted: Vec<&str> = v.respotted.iter().map(|(id, _)| id.as_str()).collect();
        for (i, b) in f.balls().iter().enumerate() {
            let got = v.balls.iter().find(|n| n.id == b.id);
            if let Some((_, r)) = v.respotted.iter().find(|(id, _)| *id == b.id) {
                prop_assert_eq!(got.map(|g| g.state.pos.xy()), Some(r.pos.xy()));
            } else if finals[i].motion.in_play() && !(b.kind == BallKind::Cue && in_hand) && !v.frame_over() {
                let got = got.map(|g| g.state.pos);
                prop_assert_eq!(got, Some(finals[i].pos), "{} moved", &b.id);
            } else {
                prop_assert!(got.is_none(), "{} should be gone", &b.id);
            }
        }
        prop_assert_eq!(v.balls.len(), v.balls.iter().filter(|b| respotted.contains(&b.id.as_str()) || f.balls().iter().any(|o| o.id == b.id)).count());
        // Only colours go back, and only colours that left the table (or the black of a tie).
        for id in &respotted {
            let i = f.balls().iter().position(|b| b.id == *id).unwrap();
            prop_assert!(Colour::of(f.balls()[i].kind).is_some());
            let tie = v.next.is_some_and(|n| n.ball_in_hand && n.on == On::Closing(Colour::Black) && v.scores[0] == v.scores[1]);
            prop_assert!(!finals[i].motion.in_play() || tie);
        }
        // The next frame is a frame.
        if let Next::Play(n) = f.next(v) {
            let again = Frame::new(n.name(), n.table().clone(), *n.params(), *n.models(), *n.options(), n.balls().to_vec(), *n.state());
            prop_assert!(again.is_ok(), "{:?}", again.err());
            // And its file reads back to the same frame.
            let text = n.to_toml(None);
            let read = snooker_rules::parse(&text, "next.toml").unwrap_or_else(|e| panic!("{e}\n{text}"));
            prop_assert_eq!(read.frame, *n);
        }
    }

    #[test]
    fn random_legal_looking_strokes_end_the_frame_or_reach_the_cap(
        reds in 1usize..=15,
        seed in any::<u64>(),
        shots in proptest::collection::vec((0.4f64..5.0, -0.05f64..0.05, any::<u32>(), -0.008f64..0.008), 80),
    ) {
        let mut f = Frame::open_table(reds, seed);
        let mut ended = false;
        for (speed, miss, pick, height) in shots {
            let s = *f.state();
            if s.ball_in_hand && f.cue_index().is_none() {
                let d = f.the_d();
                let p = f.nearest_placement([d.centre.x - 0.15, d.centre.y]).unwrap();
                f = f.with_cue_ball_at(p).unwrap();
            }
            let noms = f.legal_nominations();
            if (s.on == On::Colour || s.free_ball) && s.nominated.is_none() {
                f = f.with_nomination(Some(noms[pick as usize % noms.len()])).unwrap();
            }
            // Aim at a ball on, a little off the full-ball line.
            let on = f.balls_on();
            let target = f.balls()[on[pick as usize % on.len()]].state.pos;
            let cue = f.balls()[f.cue_index().unwrap()].state.pos;
            let d: Vec3 = target - cue;
            let strike = Cue { speed, aim: d.y.atan2(d.x) + miss, offset: [0.0, height], elevation: 0.0 };
            let stroke = f.play(&strike).unwrap_or_else(|e| panic!("{e}\n{}", f.to_toml(Some(&strike))));
            match f.next(&stroke.verdict) {
                Next::Play(n) => f = *n,
                Next::Over { winner, scores } => {
                    prop_assert!(scores[winner as usize] > scores[1 - winner as usize]);
                    ended = true;
                    break;
                }
            }
        }
        let _ = ended;
    }
}
