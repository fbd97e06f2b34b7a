//! `snooker plan`: the thesis's chapter 7 position planned and replayed through
//! `snooker simulate` to the bit, the JSON contract (formats.md, "Plan"), a snooker that
//! cannot be potted (exit 1), and bad input (exit 2, one message, nothing written).

mod common;

use common::{snooker, temp_dir};
use serde_json::Value;
use std::path::Path;

const CH7: &str = "scenes/chapter7-example.toml";

fn json(path: &std::path::Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// `snooker plan SCENE --pot red --pocket top-left --cue-to 1.5,0.5 --samples 4` and `extra`:
/// the red into the top-left pocket of the tests' small positions, with few noise samples.
fn plan_red_top_left(scene: &Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec![
        "plan",
        scene.to_str().unwrap(),
        "--pot",
        "red",
        "--pocket",
        "top-left",
        "--cue-to",
        "1.5,0.5",
        "--samples",
        "4",
    ];
    args.extend_from_slice(extra);
    snooker(&args)
}

#[test]
fn the_chapter_7_plan_replays_exactly_through_simulate() {
    let dir = temp_dir("plan-ch7");
    let (plan, scene, result) = (
        dir.join("plan.json"),
        dir.join("planned.toml"),
        dir.join("replay.json"),
    );
    let o = snooker(&[
        "plan",
        CH7,
        "--pot",
        "red",
        "--pocket",
        "middle-left",
        "--cue-to",
        "1.25,0.0262",
        "--samples",
        "32",
        "--json",
        plan.to_str().unwrap(),
        "--scene-out",
        scene.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let p = json(&plan);
    for key in [
        "scene",
        "pot",
        "pocket",
        "target",
        "reached",
        "best",
        "alternatives",
    ] {
        assert!(p.get(key).is_some(), "no `{key}` in {p}");
    }
    assert!(p["shots_simulated"].as_u64().unwrap() > 0);
    assert!(p["wall_time"].as_f64().unwrap() > 0.0);
    let best = &p["best"];
    assert_eq!(best["potted"], Value::Bool(true));
    assert_eq!(p["reached"], Value::Bool(true));
    assert!(best["distance"].as_f64().unwrap() <= 0.001);
    let rob = &best["robustness"];
    assert_eq!(rob["samples"].as_u64(), Some(32));
    // The default noise is the tournaments' standard, in the contract's keys and the new ones.
    assert_eq!(rob["noise"]["speed"].as_f64(), Some(0.075));
    assert_eq!(rob["noise"]["offset"].as_f64(), Some(0.0005));
    assert_eq!(rob["noise"]["side"].as_f64(), Some(0.0005));
    let prob = rob["pot_probability"].as_f64().unwrap();
    assert!((0.0..=1.0).contains(&prob));
    // The scene written replays the planned shot: the same final cue-ball position, to the bit.
    let o = snooker(&[
        "simulate",
        scene.to_str().unwrap(),
        "--json",
        result.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r = json(&result);
    let end = &r["final"]["cue"]["pos"];
    for k in 0..2 {
        assert_eq!(
            end[k].as_f64().unwrap().to_bits(),
            best["cue_final"][k].as_f64().unwrap().to_bits()
        );
    }
    assert!(
        r["pots"]
            .as_array()
            .unwrap()
            .iter()
            .any(|p| p["ball"] == "red")
    );
}

#[test]
fn a_ball_that_cannot_be_potted_exits_1() {
    // The red is ringed by six balls: the cue ball cannot reach it first.
    let dir = temp_dir("plan-snookered");
    let scene = dir.join("s.toml");
    std::fs::write(
        &scene,
        "balls = [{id = \"cue\", pos = [1.0, 0.9]}, {id = \"red\", pos = [2.5, 1.2]}, \
         {id = \"b0\", pos = [2.554, 1.2]}, {id = \"b1\", pos = [2.527, 1.246]}, {id = \"b2\", pos = [2.473, 1.246]}, {id = \"b3\", pos = [2.446, 1.2]}, {id = \"b4\", pos = [2.473, 1.154]}, {id = \"b5\", pos = [2.527, 1.154]}]\n",
    )
    .unwrap();
    let out = dir.join("plan.json");
    let o = plan_red_top_left(&scene, &["--json", out.to_str().unwrap()]);
    assert_eq!(
        o.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(String::from_utf8_lossy(&o.stderr).contains("no strike"));
    assert!(!out.exists());
}

#[test]
fn a_blocked_pot_is_planned_as_another_kind_and_replays() {
    // b0 stands between the red and the top-left pocket: no direct pot, but other kinds.
    let dir = temp_dir("plan-kinds");
    let scene = dir.join("s.toml");
    std::fs::write(
        &scene,
        "balls = [{id = \"cue\", pos = [1.0, 0.9]}, {id = \"red\", pos = [2.5, 1.2]}, \
         {id = \"b0\", pos = [3.0, 1.47]}]\n",
    )
    .unwrap();
    let (plan, out, result) = (
        dir.join("plan.json"),
        dir.join("planned.toml"),
        dir.join("r.json"),
    );
    let run = |kinds: &str| {
        let (plan, out) = (plan.to_str().unwrap(), out.to_str().unwrap());
        let extra = [
            "--tolerance",
            "0.005",
            "--alternatives",
            "0",
            "--kinds",
            kinds,
        ];
        plan_red_top_left(
            &scene,
            &[&extra[..], &["--json", plan, "--scene-out", out]].concat(),
        )
    };
    let o = run("direct");
    assert_eq!(
        o.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(String::from_utf8_lossy(&o.stderr).contains("no direct pot is open"));
    assert!(!plan.exists());
    let o = run("direct,double,plant,kiss");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let p = json(&plan);
    let kind = p["best"]["route"]["kind"].as_str().unwrap().to_string();
    assert!(
        ["double", "plant", "kiss"].contains(&kind.as_str()),
        "{kind}"
    );
    assert!(!p["best"]["route"]["via"].as_array().unwrap().is_empty());
    let o = snooker(&[
        "simulate",
        out.to_str().unwrap(),
        "--json",
        result.to_str().unwrap(),
    ]);
    assert!(o.status.success());
    let r = json(&result);
    for k in 0..2 {
        assert_eq!(
            r["final"]["cue"]["pos"][k].as_f64().unwrap().to_bits(),
            p["best"]["cue_final"][k].as_f64().unwrap().to_bits()
        );
    }
    assert!(
        r["pots"]
            .as_array()
            .unwrap()
            .iter()
            .any(|x| x["ball"] == "red" && x["pocket"] == "top-left")
    );
}

#[test]
fn a_plant_strikes_first_only_a_ball_plant_balls_names() {
    // b1 touches the red on its line to the top-left pocket: a set, planted through b1.
    let dir = temp_dir("plan-plant-balls");
    let scene = dir.join("s.toml");
    std::fs::write(
        &scene,
        "balls = [{id = \"cue\", pos = [1.0, 0.9]}, {id = \"red\", pos = [2.5, 1.2]}, \
         {id = \"b1\", pos = [2.4538, 1.175]}, {id = \"b2\", pos = [2.0, 0.5]}]\n",
    )
    .unwrap();
    let plan = dir.join("plan.json");
    let run = |via: &str| {
        let extra = [
            "--tolerance",
            "0.01",
            "--alternatives",
            "0",
            "--kinds",
            "plant",
        ];
        let (plan, via) = (plan.to_str().unwrap(), ["--plant-balls", via]);
        plan_red_top_left(&scene, &[&extra[..], &via, &["--json", plan]].concat())
    };
    let o = run("b1");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(json(&plan)["best"]["route"]["via"][0], "b1");
    std::fs::remove_file(&plan).unwrap();
    // Only b2 allowed: no plant is open through it.
    let o = run("b2");
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("no plant is open"));
    assert!(!plan.exists());
}

#[test]
fn bad_requests_exit_2_with_one_message_and_write_nothing() {
    let dir = temp_dir("plan-bad");
    let out = dir.join("plan.json");
    let scene = dir.join("s.toml");
    std::fs::write(
        &scene,
        "balls = [{id = \"cue\", pos = [0.698, 0.562]}, {id = \"red\", pos = [0.869, 0.681]}, \
         {id = \"blue\", pos = [2.0, 1.0]}]\n",
    )
    .unwrap();
    let base = [
        "plan",
        scene.to_str().unwrap(),
        "--json",
        out.to_str().unwrap(),
    ];
    let ok = "--pot red --pocket middle-left";
    for (extra, says) in [
        (
            "--pot pink --pocket middle-left --cue-to 1,1".to_string(),
            "--pot",
        ),
        (
            "--pot cue --pocket middle-left --cue-to 1,1".to_string(),
            "--pot",
        ),
        (
            "--pot red --pocket side --cue-to 1,1".to_string(),
            "--pocket",
        ),
        (format!("{ok} --cue-to 9,1"), "--cue-to"),
        (format!("{ok} --cue-to 2.01,1.0"), "--cue-to"),
        (format!("{ok} --cue-to 1;1"), "--cue-to"),
        (format!("{ok} --cue-to 1,1 --noise aim=x"), "--noise"),
        (format!("{ok} --cue-to 1,1 --kinds direct,bank"), "--kinds"),
        (format!("{ok} --cue-to 1,1 --noise blur=0.1"), "--noise"),
        // usize::MAX overflowed the search's count (a panic in a debug build).
        (
            format!("{ok} --cue-to 1,1 --alternatives 18446744073709551615"),
            "--alternatives",
        ),
        (format!("{ok} --cue-to 1,1 --noise standard*-1"), "--noise"),
        // The old spelling: speed as a fraction beside one offset is refused, not misread.
        (
            format!("{ok} --cue-to 1,1 --noise aim=0.002,speed=0.02,offset=0.001"),
            "m/s",
        ),
        (
            format!("{ok} --cue-to 1,1 --bounds speed=0.3..40"),
            "--bounds",
        ),
        // A variable twice kept its last interval silently.
        (
            format!("{ok} --cue-to 1,1 --bounds speed=1..2,speed=1..3"),
            "`speed` is given twice",
        ),
        // More samples than memory holds records for: refused, not a panic (capacity
        // overflow) or an allocation the machine cannot make.
        (
            format!("{ok} --cue-to 1,1 --samples 18446744073709551615"),
            "--samples",
        ),
        (
            format!("{ok} --cue-to 1,1 --samples 1000000000"),
            "--samples",
        ),
        (
            format!("{ok} --cue-to 1,1 --plant-balls pink"),
            "--plant-balls",
        ),
        (
            format!("{ok} --cue-to 1,1 --plant-balls cue"),
            "--plant-balls",
        ),
        (
            format!("{ok} --cue-to 1,1 --plant-balls red"),
            "--plant-balls",
        ),
        (
            format!("{ok} --cue-to 1,1 --plant-balls blue,,"),
            "--plant-balls",
        ),
        (
            format!("{ok} --cue-to 1,1 --plant-balls blue,blue"),
            "--plant-balls",
        ),
    ] {
        let extra: Vec<&str> = extra.split_whitespace().collect();
        let args: Vec<&str> = base.iter().copied().chain(extra).collect();
        let o = snooker(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
        assert!(!out.exists(), "{args:?}");
    }
}

#[test]
fn a_plan_whose_shots_cannot_finish_says_so() {
    // Every shot is still moving at 0.2 s: the message blamed the lines alone.
    let dir = temp_dir("plan-unfinished");
    let scene = dir.join("s.toml");
    std::fs::write(
        &scene,
        "balls = [{id = \"cue\", pos = [1.0, 0.9]}, {id = \"red\", pos = [2.5, 1.2]}]\n\
         [sim]\nmax_time = 0.2\n",
    )
    .unwrap();
    let o = plan_red_top_left(&scene, &[]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("no strike")
            && err.contains("could not finish within the scene's [sim] limits"),
        "{err}"
    );
}

#[test]
fn the_contracts_noise_offset_is_written_when_side_and_height_differ() {
    // formats.md, "Plan": robustness.noise.offset is a contract key; it was left out whenever
    // the side and height noise differed. Read as an outside script would.
    let dir = temp_dir("plan-offset");
    let (scene, plan) = (dir.join("s.toml"), dir.join("plan.json"));
    std::fs::write(
        &scene,
        "balls = [{id = \"cue\", pos = [1.0, 0.9]}, {id = \"red\", pos = [2.5, 1.2]}]\n",
    )
    .unwrap();
    let noise = "standard,side=0.001";
    let o = plan_red_top_left(
        &scene,
        &["--noise", noise, "--json", plan.to_str().unwrap()],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let p = json(&plan);
    let alternatives = p["alternatives"].as_array().unwrap();
    for shot in std::iter::once(&p["best"]).chain(alternatives) {
        let n = &shot["robustness"]["noise"];
        let (side, height) = (n["side"].as_f64().unwrap(), n["height"].as_f64().unwrap());
        assert_eq!((side, height), (0.001, 0.0005), "{n}");
        let rms = (0.5 * (side * side + height * height)).sqrt();
        assert_eq!(n["offset"].as_f64(), Some(rms), "{n}");
    }
}

#[test]
fn a_ball_given_a_velocity_in_the_scene_is_not_planned_as_at_rest() {
    // The scene labelled every listed ball at rest until it was simulated, and the planner,
    // reading the label, planned to pot a red that was rolling away.
    let dir = temp_dir("plan-moving");
    let (cue, red) = (
        "{id = \"cue\", pos = [1.0, 0.9]}",
        "{id = \"red\", pos = [2.5, 1.2]}",
    );
    for (balls, flag) in [
        (
            format!("{cue}, {{id = \"red\", pos = [2.5, 1.2], vel = [0.3, 0.0, 0.0]}}"),
            "--pot",
        ),
        (
            format!("{cue}, {{id = \"red\", pos = [2.5, 1.2], spin = [0.0, 0.0, 40.0]}}"),
            "--pot",
        ),
        (
            format!("{{id = \"cue\", pos = [1.0, 0.9], vel = [0.0, 0.2, 0.0]}}, {red}"),
            "--cue-ball",
        ),
    ] {
        let scene = dir.join("s.toml");
        std::fs::write(&scene, format!("balls = [{balls}]\n")).unwrap();
        let out = dir.join("plan.json");
        let o = plan_red_top_left(&scene, &["--json", out.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{balls}: {err}");
        assert!(err.contains(flag) && err.contains("at rest"), "{err}");
        assert!(!out.exists());
    }
}
