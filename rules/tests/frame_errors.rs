//! Frames that cannot be played are refused when read, with the key at fault (and its line):
//! everything formats.md calls a frame error, and what the rules make one.

use snooker_scene::SceneError;

/// The six colours on their spots.
const COLOURS: &str = r#"
[[balls]]
id = "yellow"
pos = [0.737, 0.597]
[[balls]]
id = "green"
pos = [0.737, 1.181]
[[balls]]
id = "brown"
pos = [0.737, 0.889]
[[balls]]
id = "blue"
pos = [1.7845, 0.889]
[[balls]]
id = "pink"
pos = [2.67675, 0.889]
[[balls]]
id = "black"
pos = [3.245, 0.889]
"#;

const CUE: &str = "[cue]\nball = \"cue\"\nspeed = 1.0\naim = 0.0\n";

fn err(text: &str) -> SceneError {
    match snooker_rules::parse(text, "bad.toml") {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => e,
    }
}

fn frame(table: &str, balls: &str) -> String {
    format!("[frame]\n{table}\n{balls}")
}

fn red_and_cue() -> String {
    format!(
        "{COLOURS}[[balls]]\nid = \"cue\"\npos = [1.2, 0.4]\n[[balls]]\nid = \"red1\"\npos = [2.0, 0.4]\n"
    )
}

#[track_caller]
fn refused(text: &str, key: &str, reason: &str) {
    let e = err(text);
    assert_eq!(e.key, key, "{e}");
    assert!(e.reason.contains(reason), "{e}");
    assert_eq!(e.file, "bad.toml");
}

#[test]
fn a_colour_on_with_a_strike_needs_a_nomination() {
    refused(
        &format!("{CUE}{}", frame("on = \"colour\"", &red_and_cue())),
        "frame.nominated",
        "needs the ball nominated",
    );
    // Without a strike there is nothing to judge yet: the frame is fine.
    assert!(snooker_rules::parse(&frame("on = \"colour\"", &red_and_cue()), "ok.toml").is_ok());
    // A free ball too.
    refused(
        &format!(
            "{CUE}{}",
            frame("on = \"red\"\nfree_ball = true", &red_and_cue())
        ),
        "frame.nominated",
        "and a free ball",
    );
}

#[test]
fn an_on_that_contradicts_the_balls_is_refused_with_its_line() {
    let no_red = format!("{COLOURS}[[balls]]\nid = \"cue\"\npos = [1.2, 0.4]\n");
    let text = frame("on = \"red\"", &no_red);
    let e = err(&text);
    assert_eq!(e.key, "frame.on");
    assert!(e.reason.contains("no red is on the table"), "{e}");
    assert!(e.reason.contains("(line 2, column 6)"), "{e}");
    refused(
        &frame("on = \"green\"", &red_and_cue()),
        "frame.on",
        "reds remain",
    );
    refused(
        &frame("on = \"green\"", &no_red),
        "frame.on",
        "the yellow is still on the table",
    );
    let blue_gone = no_red.replace(
        "id = \"blue\"\npos = [1.7845, 0.889]",
        "id = \"red1\"\npos = [1.7845, 0.889]",
    );
    refused(
        &frame("on = \"red\"", &blue_gone),
        "frame.on",
        "the blue is not on the table",
    );
    refused(
        &frame("on = \"purple\"", &no_red),
        "frame.on",
        "unknown ball on",
    );
    let no_black = red_and_cue().replace("id = \"black\"", "id = \"red9\"");
    refused(
        &frame("on = \"red\"", &no_black),
        "balls",
        "the black is not on the table",
    );
}

#[test]
fn malformed_scores_are_refused() {
    for (scores, why) in [
        ("[1]", "got 1 values"),
        ("[1, 2, 3]", "got 3 values"),
        ("[-1, 0]", "got -1"),
        ("[1.5, 0]", "got 1.5"),
        ("[\"a\", 0]", "got \"a\""),
        ("7", "two non-negative integers"),
    ] {
        refused(
            &frame(&format!("on = \"red\"\nscores = {scores}"), &red_and_cue()),
            "frame.scores",
            why,
        );
    }
}

#[test]
fn a_player_is_0_or_1() {
    refused(
        &frame("on = \"red\"\nto_play = 2", &red_and_cue()),
        "frame.to_play",
        "must be 0 or 1",
    );
    refused(
        &frame("on = \"red\"\nfirst_player = -1", &red_and_cue()),
        "frame.first_player",
        "got -1",
    );
}

#[test]
fn a_cue_ball_in_hand_goes_in_the_d_touching_no_ball() {
    // Outside the D (the red and cue of red_and_cue are far from it).
    refused(
        &format!(
            "{CUE}{}",
            frame("on = \"red\"\nball_in_hand = true", &red_and_cue())
        ),
        "balls[6].pos",
        "outside it",
    );
    // Touching the brown.
    let touching = red_and_cue().replace("pos = [1.2, 0.4]", "pos = [0.6846, 0.889]");
    let e = err(&format!(
        "{CUE}{}",
        frame("on = \"red\"\nball_in_hand = true", &touching)
    ));
    assert_eq!(e.key, "balls[6].pos", "{e}");
    assert!(
        e.reason.contains("touching a ball") && e.reason.contains("\"brown\""),
        "{e}"
    );
    assert!(e.reason.contains("line"), "{e}");
    // In the D, clear: played.
    let placed = red_and_cue().replace("pos = [1.2, 0.4]", "pos = [0.6, 1.0]");
    assert!(
        snooker_rules::parse(
            &format!(
                "{CUE}{}",
                frame("on = \"red\"\nball_in_hand = true", &placed)
            ),
            "ok.toml"
        )
        .is_ok()
    );
    // Not in hand and not on the table.
    let no_cue = red_and_cue().replace("id = \"cue\"", "id = \"red2\"");
    refused(
        &frame("on = \"red\"", &no_cue),
        "frame.ball_in_hand",
        "no cue ball on the table",
    );
    // In hand, not listed, and struck: the strike has no ball to strike until it is placed.
    let e = err(&format!(
        "{CUE}{}",
        frame("on = \"red\"\nball_in_hand = true", &no_cue)
    ));
    assert_eq!(e.key, "cue.ball", "{e}");
    assert!(
        e.reason.contains("no ball with id \"cue\"")
            && e.reason
                .contains("a cue ball in hand is struck from where it is placed"),
        "{e}"
    );
    // The same frame without a strike is a frame to place the cue ball in.
    assert!(
        snooker_rules::parse(
            &frame("on = \"red\"\nball_in_hand = true", &no_cue),
            "ok.toml"
        )
        .is_ok()
    );
}

#[test]
fn nominations_must_be_playable() {
    refused(
        &frame("on = \"red\"\nnominated = \"black\"", &red_and_cue()),
        "frame.nominated",
        "nothing to nominate",
    );
    refused(
        &frame("on = \"colour\"\nnominated = \"red\"", &red_and_cue()),
        "frame.nominated",
        "not a colour to nominate",
    );
    let closing = COLOURS.to_string() + "[[balls]]\nid = \"cue\"\npos = [1.2, 0.4]\n";
    refused(
        &frame("on = \"yellow\"\nnominated = \"black\"", &closing),
        "frame.nominated",
        "a free ball is needed",
    );
    refused(
        &frame(
            "on = \"yellow\"\nnominated = \"yellow\"\nfree_ball = true",
            &closing,
        ),
        "frame.nominated",
        "other than the ball on",
    );
    refused(
        &frame("on = \"colour\"\nfree_ball = true", &red_and_cue()),
        "frame.free_ball",
        "never on = \"colour\"",
    );
}

#[test]
fn only_the_balls_of_snooker_at_rest_on_the_snooker_table() {
    let extra = |b: &str| format!("{}[[balls]]\n{b}\n", red_and_cue());
    refused(
        &frame("on = \"red\"", &extra("id = \"spot\"\npos = [2.5, 1.5]")),
        "balls[8].id",
        "not a ball of snooker",
    );
    refused(
        &frame("on = \"red\"", &extra("id = \"black2\"\npos = [2.5, 1.5]")),
        "balls[8].id",
        "a second black",
    );
    refused(
        &frame("on = \"red\"", &extra("id = \"white\"\npos = [2.5, 1.5]")),
        "balls[8].id",
        "a second cue ball",
    );
    refused(
        &frame(
            "on = \"red\"",
            &extra("id = \"red2\"\npos = [2.5, 1.5]\nvel = [0.1, 0, 0]"),
        ),
        "balls[8].vel",
        "moving",
    );
    refused(
        &format!(
            "[table]\nkind = \"open\"\n{}",
            frame("on = \"red\"", &red_and_cue())
        ),
        "table.kind",
        "snooker table",
    );
    refused(
        &format!(
            "[sim]\nhorizon = 1.0\n{}",
            frame("on = \"red\"", &red_and_cue())
        ),
        "sim.horizon",
        "no horizon",
    );
    refused(
        &format!(
            "[cue]\nball = \"red1\"\nspeed = 1.0\naim = 0.0\n{}",
            frame("on = \"red\"", &red_and_cue())
        ),
        "cue.ball",
        "strikes the cue ball",
    );
}

#[test]
fn the_frame_table_is_required_and_checked_like_any_other() {
    refused(&red_and_cue(), "frame", "needs its [frame] table");
    let e = err(&frame("on = \"red\"\nfree_bal = true", &red_and_cue()));
    assert_eq!(e.key, "frame.free_bal", "{e}");
    assert!(
        e.reason.contains("unknown field") && e.reason.contains("line 3"),
        "{e}"
    );
    // The scene's own checks are the scene crate's, with their keys.
    let e = err(&frame(
        "on = \"red\"",
        &red_and_cue().replace("[2.0, 0.4]", "[1.21, 0.4]"),
    ));
    assert_eq!(e.key, "balls[7].pos", "{e}");
    assert!(e.reason.contains("overlaps"), "{e}");
}

#[test]
fn a_layout_ball_is_named_as_the_scene_crate_names_it() {
    // The break-off layout's cue ball is in the D: with the rack, the colours and a strike,
    // a frame; a layout ball at fault is named `layout (id)`.
    assert!(
        snooker_rules::parse(
            &format!("layout = \"break-off\"\n{CUE}[frame]\non = \"red\"\nball_in_hand = true\n"),
            "ok.toml"
        )
        .is_ok()
    );
    let e = err("layout = \"break-off\"\n[frame]\non = \"yellow\"\n");
    assert_eq!(e.key, "frame.on", "{e}");
}

#[test]
fn a_frame_built_in_code_is_checked_for_what_a_file_cannot_say() {
    // A file gives positions in plan and its limits are checked as it is read; `Frame::new`
    // took a ball floating above the cloth, and a NaN max_time, from a Rust caller.
    let read = snooker_rules::parse(&frame("on = \"red\"", &red_and_cue()), "ok.toml")
        .unwrap()
        .frame;
    // The frame read, rebuilt with another table, balls or limits.
    let rebuild = |table: snooker_engine::Table,
                   balls: Vec<snooker_engine::Ball>,
                   options: snooker_engine::SimOptions| {
        snooker_rules::Frame::new(
            read.name(),
            table,
            *read.params(),
            *read.models(),
            options,
            balls,
            *read.state(),
        )
    };
    let with_balls = |balls| rebuild(read.table().clone(), balls, *read.options());
    let with_table = |table| rebuild(table, read.balls().to_vec(), *read.options());
    assert!(with_balls(read.balls().to_vec()).is_ok());
    let mut floating = read.balls().to_vec();
    floating[2].state.pos.z += 0.05;
    let e = with_balls(floating).unwrap_err();
    assert_eq!(e.key.to_string(), "balls[2].pos", "{e}");
    assert!(e.to_string().contains("off the cloth"), "{e}");
    let nan = snooker_engine::SimOptions {
        max_time: f64::NAN,
        ..*read.options()
    };
    let e = rebuild(read.table().clone(), read.balls().to_vec(), nan).unwrap_err();
    assert_eq!(e.key.to_string(), "sim.max_time", "{e}");
    // A table no frame file describes: its file (to_toml) wrote only the pocket sizes and
    // read back another frame.
    let other = snooker_engine::Table::snooker(&snooker_engine::SnookerDims {
        length: 3.0,
        ..Default::default()
    });
    let e = with_table(other).unwrap_err();
    assert_eq!(e.key.to_string(), "table", "{e}");
    let mut moved = read.table().clone();
    moved.cushions[0].start.x += 0.01;
    moved.cushions[0].end.x += 0.01;
    let e = with_table(moved).unwrap_err();
    assert_eq!(e.key.to_string(), "table", "{e}");
    // Pocket sizes are the file's to choose: that table reads back.
    let f = with_table(snooker_engine::Table::snooker(
        &snooker_engine::SnookerDims {
            corner_mouth: 0.1,
            ..Default::default()
        },
    ))
    .unwrap();
    let back = snooker_rules::parse(&f.to_toml(None), "back.toml")
        .unwrap()
        .frame;
    assert_eq!(back, f);
}

/// A score past MAX_SCORE is refused (before, scores up to the 32-bit limit were read and a
/// foul's points saturated there: 0-4294967293 plus 4 gave 0-4294967295, and a black potted
/// at 4294967290-4294967295 made a false tie); at the limit a foul adds its full points.
#[test]
fn a_score_past_the_limit_is_refused_and_one_at_it_adds_up() {
    let max = snooker_rules::state::MAX_SCORE;
    refused(
        &frame(
            &format!("on = \"red\"\nscores = [0, {}]", max + 1),
            &red_and_cue(),
        ),
        "frame.scores",
        "is above 1000000000",
    );
    // Player 0 strikes the cue ball away from every ball: no ball hit, a foul of 4.
    let text = format!(
        "[cue]\nball = \"cue\"\nspeed = 0.5\naim = 3.14159\n{}",
        frame(
            &format!("on = \"red\"\nscores = [0, {max}]"),
            &red_and_cue()
        )
    );
    let f = snooker_rules::parse(&text, "at-limit.toml").unwrap();
    let setup = f.frame.setup(&f.strike.unwrap()).unwrap();
    let shot = snooker_engine::simulate(&setup, f.frame.options()).unwrap();
    let v = f.frame.judge(&shot).unwrap();
    assert_eq!(v.scores, [0, max + 4], "{:?}", v.foul);
}
