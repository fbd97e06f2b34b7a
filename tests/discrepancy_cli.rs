//! `snooker synth` and `snooker discrepancy` from the command line (issue 6): hidden effects
//! found from files, the thesis's own measurements (Table I with the head-on collisions, the
//! cushion rebounds), the report files, and bad input (one message naming the file and the key
//! or the line and column; exit code 2; nothing written).

mod common;

use common::{snooker, temp_dir};
use rerun::external::re_log_encoding::DecoderApp;
use rerun::log::{Chunk, LogMsg};
use serde_json::Value;
use std::path::Path;

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The points logged over time at `entity` of a recording: (time ns, position).
fn overlay_points(rrd: &Path, entity: &str) -> Vec<(i64, [f32; 3])> {
    let bytes = std::fs::read(rrd).unwrap();
    let component = rerun::Points3D::descriptor_positions().component;
    let mut out = Vec::new();
    for msg in DecoderApp::decode_lazy(bytes.as_slice()) {
        let LogMsg::ArrowMsg(_, arrow) = msg.expect("a valid .rrd stream") else {
            continue;
        };
        let chunk = Chunk::from_arrow_msg(&arrow).expect("a valid chunk");
        if chunk.is_static() || chunk.entity_path().to_string().trim_start_matches('/') != entity {
            continue;
        }
        let Some(times) = chunk
            .timelines()
            .get(&rerun::TimelineName::from(snooker::record::TIMELINE))
        else {
            continue;
        };
        let times = times.times_raw().to_vec();
        for (t, v) in times
            .into_iter()
            .zip(chunk.iter_component::<rerun::components::Position3D>(component))
        {
            for p in v.iter() {
                out.push((t, [p.x(), p.y(), p.z()]));
            }
        }
    }
    out
}

/// Mean relative error of the observables of shots whose name starts with `prefix`.
fn mean_error(state: &Value, prefix: &str) -> f64 {
    let rows: Vec<&Value> = state["location"]["observables"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|r| r["shot"].as_str().unwrap().starts_with(prefix))
        .collect();
    rows.iter()
        .map(|r| {
            let m = r["measured"].as_f64().unwrap();
            (r["simulated"].as_f64().unwrap() - m).abs() / m
        })
        .sum::<f64>()
        / rows.len() as f64
}

#[test]
fn a_hidden_slope_is_found_from_files_with_a_full_report() {
    let dir = temp_dir("slope");
    let data = dir.join("slope.toml");
    let o = snooker(&[
        "synth",
        "scenes/one-cushion.toml",
        "--effect",
        "table_slope=0.001,-0.0006",
        "--fps",
        "100",
        "--noise",
        "0.5",
        "--seed",
        "3",
        "-o",
        s(&data),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in ["slope.toml", "slope.csv", "slope.scene.toml"] {
        assert!(dir.join(f).is_file(), "{f} not written");
    }
    let report = dir.join("report");
    let out = dir.join("r.json");
    let o = snooker(&[
        "discrepancy",
        s(&data),
        "--report",
        s(&report),
        "--json",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("named: table_slope"), "{text}");
    let doc = json(&out);
    // formats.md's keys.
    assert_eq!(doc["named"], serde_json::json!(["table_slope"]));
    assert_eq!(doc["unexplained"], false);
    assert!(doc["baseline_gap"]["rms"].as_f64().unwrap() > 0.01);
    assert!(doc["baseline_gap"]["samples"].as_u64().unwrap() > 100);
    assert!(doc["final_gap"]["rms"].as_f64().unwrap() < 1.5 * 5e-4);
    let step = &doc["steps"][0];
    assert_eq!(step["effect"], "table_slope");
    let sx = step["params"]["slope_x"].as_f64().unwrap();
    let sy = step["params"]["slope_y"].as_f64().unwrap();
    assert!(
        (sx - 0.001).abs() < 1e-4 && (sy + 0.0006).abs() < 6e-5,
        "{sx} {sy}"
    );
    assert!(step["uncertainties"]["slope_x"].as_f64().unwrap() > 0.0);
    assert!(step["gap"]["rms"].as_f64().unwrap() < 1.5 * 5e-4);
    for f in [
        "report.json",
        "summary.txt",
        "tracks.png",
        "residuals.png",
        "overlay.rrd",
    ] {
        let p = report.join(f);
        assert!(
            p.is_file() && std::fs::metadata(&p).unwrap().len() > 100,
            "{f}"
        );
    }
    assert_eq!(json(&report.join("report.json")), doc);
    // The overlay recording holds every measured centroid of the tracks file, at its time.
    let csv = std::fs::read_to_string(dir.join("slope.csv")).unwrap();
    let rrd = report.join("overlay.rrd");
    for ball in ["cue"] {
        let measured: Vec<(f64, f64, f64)> = csv
            .lines()
            .skip(1)
            .map(|l| l.split(',').collect::<Vec<_>>())
            .filter(|f| f[1] == ball)
            .map(|f| {
                (
                    f[0].parse().unwrap(),
                    f[2].parse().unwrap(),
                    f[3].parse().unwrap(),
                )
            })
            .collect();
        assert!(measured.len() > 100);
        let logged = overlay_points(&rrd, &format!("measured/{ball}"));
        assert_eq!(logged.len(), measured.len(), "measured/{ball}");
        for ((t, p), (mt, mx, my)) in logged.iter().zip(&measured) {
            assert!((*t as f64 * 1e-9 - mt).abs() < 1e-9, "{t} {mt}");
            assert!((p[0] as f64 - mx).abs() < 1e-6 && (p[1] as f64 - my).abs() < 1e-6);
        }
        let start = overlay_points(&rrd, &format!("start_model/{ball}"));
        assert_eq!(start.len(), measured.len(), "start_model/{ball}");
    }
}

/// The workflow's JSON report on `data`, from the ideal ball-ball model.
fn workflow(dir: &Path, data: &str) -> Value {
    let out = dir.join("report.json");
    let o = snooker(&[
        "discrepancy",
        data,
        "--model",
        "data/discrepancy/ideal-ball.toml",
        "--json",
        s(&out),
        "-q",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    json(&out)
}

#[test]
fn the_thesis_ball_ball_collisions_name_restitution_and_friction() {
    // Table I alone, from the ideal model: the workflow names ball-ball friction and the mean
    // speed error falls from the 6.4% of Wallace and Schroeder to 3.7%; restitution then
    // lowers the BIC by only ~1 with these ten numbers, so it is not named.
    let dir = temp_dir("table-i");
    let doc = workflow(&dir, "data/discrepancy/table-i.toml");
    assert_eq!(doc["named"], serde_json::json!(["ball_friction"]));
    // Observables only, no tracks: a position gap of 0 is over no samples, and says so (it
    // read as a perfect fit).
    for gap in ["baseline_gap", "final_gap"] {
        assert_eq!(doc[gap]["samples"].as_u64(), Some(0), "{gap}: {}", doc[gap]);
    }
    assert_eq!(doc["final_observable_gap"]["samples"].as_u64(), Some(10));
    let before = mean_error(&doc["baseline"], "table-i");
    let after = mean_error(&doc["final"], "table-i");
    assert!((before - 0.064).abs() < 0.002, "{before}");
    assert!(after < 0.04, "{after}");

    // With the thesis's head-on collisions too (5.1.3.3), which fix e as they did for the
    // thesis's own fit (6.1.4.3): both effects are named and Table I is matched to 3% or less.
    let doc = workflow(&dir, "data/discrepancy/ball-ball.toml");
    let mut named: Vec<&str> = doc["named"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    named.sort();
    assert_eq!(named, ["ball_friction", "ball_restitution"]);
    let before = mean_error(&doc["baseline"], "table-i");
    let after = mean_error(&doc["final"], "table-i");
    assert!((before - 0.064).abs() < 0.002, "{before}");
    assert!(after <= 0.03, "Table I mean error after: {after}");
    let e = doc["final_model"]["params"]["e_ball"].as_f64().unwrap();
    let mu = doc["final_model"]["params"]["mu_ball"].as_f64().unwrap();
    // The thesis fitted 0.89 and 0.05, Marlow 0.92 and 0.06 (thesis 6.1.4.3).
    assert!(
        (0.85..0.95).contains(&e) && (0.03..0.1).contains(&mu),
        "{e} {mu}"
    );
}

#[test]
fn the_thesis_cushion_rebounds_name_the_compliant_cushion() {
    let dir = temp_dir("cushion");
    let report = dir.join("report");
    let o = snooker(&[
        "discrepancy",
        "data/discrepancy/cushion-rebound.toml",
        "--report",
        s(&report),
        "-q",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let doc = json(&report.join("report.json"));
    // Issue 25: the compliant cushion explains the 31 rebounds to the stated noise.
    assert_eq!(doc["named"][0], "compliant_cushion");
    assert_eq!(doc["unexplained"], false);
    let chi2_dof = doc["final"]["reduced_chi2"].as_f64().unwrap();
    assert!(chi2_dof <= 1.5, "{chi2_dof}");
    // The gap above 2.5 m/s (where the thesis's rigid cushion departs from the data) shrinks.
    let fast_rms = |state: &Value| {
        let rows: Vec<f64> = state["location"]["observables"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|r| r["event_speed"].as_f64().unwrap() > 2.5)
            .map(|r| r["simulated"].as_f64().unwrap() - r["measured"].as_f64().unwrap())
            .collect();
        (rows.iter().map(|d| d * d).sum::<f64>() / rows.len() as f64).sqrt()
    };
    let (before, after) = (fast_rms(&doc["baseline"]), fast_rms(&doc["final"]));
    assert!(before > 0.15, "{before}");
    assert!(after < 0.3 * before, "{before} -> {after}");
    assert!(report.join("observables.png").is_file());
}

#[test]
fn table_i_cross_validated_holds_out_half_the_collisions() {
    let dir = temp_dir("crossval");
    let report = dir.join("report");
    let o = snooker(&[
        "discrepancy",
        "data/discrepancy/ball-ball.toml",
        "--model",
        "data/discrepancy/ideal-ball.toml",
        "--cross-validate",
        "table-i",
        "--report",
        s(&report),
        "-q",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rows = json(&report.join("cross-validation.json"));
    let rows = rows.as_array().unwrap();
    assert_eq!(rows.len(), 4);
    for r in rows {
        let folds = r["folds"].as_array().unwrap();
        assert_eq!(folds.len(), 2);
        // Each fold tests on the collisions the other trained on.
        assert_eq!(folds[0]["test"], folds[1]["train"]);
        assert_eq!(folds[0]["train"], folds[1]["test"]);
    }
    let test_error = |k: usize| rows[k]["test_error"].as_f64().unwrap();
    // The thesis's model beats the ideal one on collisions it never saw.
    assert!(test_error(0) < 0.04 && test_error(1) > 0.05, "{rows:?}");
    // With nothing fitted, train and test errors are the model's on each half.
    assert!(report.join("cross-validation.md").is_file());
    let bad = snooker(&[
        "discrepancy",
        "data/discrepancy/ball-ball.toml",
        "--cross-validate",
        "nope",
    ]);
    assert_eq!(bad.status.code(), Some(2));
}

/// Runs `discrepancy` on `data` and checks it fails as bad input naming `needles`.
fn rejects(dir: &Path, data: &str, files: &[(&str, &str)], needles: &[&str]) {
    for (name, text) in files {
        std::fs::write(dir.join(name), text).unwrap();
    }
    std::fs::write(dir.join("d.toml"), data).unwrap();
    let out = dir.join("never.json");
    let o = snooker(&["discrepancy", s(&dir.join("d.toml")), "--json", s(&out)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "one message: {err}");
    for n in needles {
        assert!(err.contains(n), "{n:?} not in: {err}");
    }
    assert!(!out.exists(), "nothing is written on bad input");
}

#[test]
fn bad_data_files_are_rejected_with_file_key_line_and_column() {
    let dir = temp_dir("bad");
    let scene = std::fs::read_to_string("scenes/one-cushion.toml").unwrap();
    let scene_file = ("s.toml", scene.as_str());
    let good = "scene = \"s.toml\"\ntracks = \"t.csv\"\nnoise = 0.0005\nfit = [\"strike.speed\"]\n";
    let csv = |rows: &str| format!("# comment\nt,ball,x,y\n{rows}");
    rejects(
        &dir,
        "tracks = \"t.csv\"\n",
        &[],
        &["d.toml", "scene", "missing"],
    );
    rejects(
        &dir,
        good,
        &[
            scene_file,
            ("t.csv", &csv("0.0,cue,1.0,0.5\n0.01,cue,1.0x,0.5\n")),
        ],
        &["t.csv", "line 4, column 10", "x (m)", "1.0x"],
    );
    rejects(
        &dir,
        good,
        &[scene_file, ("t.csv", &csv("0.0,ghost,1.0,0.5\n"))],
        &["t.csv", "line 3, column 5", "ghost"],
    );
    rejects(
        &dir,
        good,
        &[
            scene_file,
            ("t.csv", &csv("0.02,cue,1.0,0.5\n0.01,cue,1.0,0.5\n")),
        ],
        &["t.csv", "line 4", "time order"],
    );
    rejects(
        &dir,
        good,
        &[scene_file, ("t.csv", "t,ball,x\n0,cue,1\n")],
        &["t.csv", "line 1", "header"],
    );
    rejects(
        &dir,
        &good.replace("strike.speed", "cue.velocity"),
        &[scene_file, ("t.csv", &csv("0.0,cue,1.0,0.5\n"))],
        &["d.toml", "fit[0]", "velocity"],
    );
    rejects(
        &dir,
        &good.replace("noise = 0.0005\n", ""),
        &[scene_file, ("t.csv", &csv("0.0,cue,1.0,0.5\n"))],
        &["d.toml", "noise", "missing"],
    );
    rejects(
        &dir,
        &good.replace("noise = 0.0005", "noise = -1"),
        &[scene_file, ("t.csv", &csv("0.0,cue,1.0,0.5\n"))],
        &["d.toml", "noise"],
    );
    rejects(
        &dir,
        &(good.to_string() + "colour = 1\n"),
        &[scene_file, ("t.csv", &csv("0.0,cue,1.0,0.5\n"))],
        &["d.toml", "colour"],
    );
    rejects(
        &dir,
        "scene = \"s.toml\"\nobservables = \"o.csv\"\n",
        &[
            scene_file,
            (
                "o.csv",
                "shot,ball,quantity,when,value,sigma\n,cue,speed,after:cushion#1,1.0,0.02\n",
            ),
        ],
        &["o.csv", "line 2, column 12", "cushion"],
    );
    rejects(
        &dir,
        "scene = \"s.toml\"\nobservables = \"o.csv\"\n",
        &[
            scene_file,
            (
                "o.csv",
                "shot,ball,quantity,when,value,sigma\n,cue,speed,after:ball_cushion#1,1.0,0\n",
            ),
        ],
        &["o.csv", "line 2", "sigma"],
    );
    // A measurement repeated would weigh twice (Table I with one row doubled named nothing),
    // as a track's sample repeated is refused.
    rejects(
        &dir,
        "scene = \"s.toml\"\nobservables = \"o.csv\"\n",
        &[
            scene_file,
            (
                "o.csv",
                "shot,ball,quantity,when,value,sigma\n,cue,speed,after:ball_cushion#1,1.0,0.02\n\
                 ,cue,speed,after:ball_cushion#1,1.1,0.02\n",
            ),
        ],
        &["o.csv", "line 3", "measured twice (line 2 too)"],
    );
    // Too few measured values for what `fit` asks: bad input (it was exit 1, naming no key).
    rejects(
        &dir,
        &good.replace("strike.speed", "cue.vel\", \"cue.spin"),
        &[scene_file, ("t.csv", &csv("0.0,cue,1.0,0.5\n"))],
        &["d.toml", "key `fit`", "2 residuals", "5 unknowns"],
    );
    rejects(
        &dir,
        "scene = \"missing.toml\"\nobservables = \"o.csv\"\n",
        &[],
        &["missing.toml", "d.toml"],
    );
}

/// Numbers that parse but lie beyond any measurement (a noise of 1e-300 m, a centre 1e300 m
/// away, a sample 1e9 s after the strike, an observable's value of 1e300 or its sigma of
/// 1e-300) are refused naming the file
/// and the key or the line and column. They were accepted, and the residuals divided by the
/// noise or sigma overflowed: the report said `null` (JSON for infinity) for its gaps,
/// chi-squared and BIC.
#[test]
fn numbers_beyond_any_measurement_are_rejected_not_reported_as_null() {
    let dir = temp_dir("beyond");
    let scene = std::fs::read_to_string("scenes/one-cushion.toml").unwrap();
    let scene_file = ("s.toml", scene.as_str());
    let good = "scene = \"s.toml\"\ntracks = \"t.csv\"\nnoise = 0.0005\nfit = [\"strike.speed\"]\n";
    let tracks = ("t.csv", "t,ball,x,y\n0.0,cue,0.5,0.4\n0.01,cue,0.52,0.4\n");
    rejects(
        &dir,
        &good.replace("noise = 0.0005", "noise = 1e-300"),
        &[scene_file, tracks],
        &["d.toml", "noise", "1e-300"],
    );
    rejects(
        &dir,
        good,
        &[scene_file, ("t.csv", "t,ball,x,y\n0.0,cue,1e300,0.4\n")],
        &["t.csv", "line 2, column 9", "x (m)"],
    );
    rejects(
        &dir,
        good,
        &[scene_file, ("t.csv", "t,ball,x,y\n0.0,cue,0.5,-1e155\n")],
        &["t.csv", "line 2, column 13", "y (m)"],
    );
    // A sample long after the shot must have ended (`[sim] max_time`, an hour by default):
    // the report's plot sampled the simulated paths every 5 ms up to it (3.2 TB for 1e9 s)
    // and the process aborted after writing the JSON.
    rejects(
        &dir,
        good,
        &[
            scene_file,
            ("t.csv", "t,ball,x,y\n0.0,cue,0.5,0.4\n1e9,cue,0.5,0.4\n"),
        ],
        &["t.csv", "line 3, column 1", "max_time"],
    );
    let obs = |row: &str| format!("shot,ball,quantity,when,value,sigma\n{row}\n");
    for (row, at) in [
        (
            ",cue,speed,after:ball_cushion#1,1e300,0.02",
            "line 2, column 33",
        ),
        (
            ",cue,heading,after:ball_cushion#1,1e200,1",
            "line 2, column 35",
        ),
        (
            ",cue,speed,after:ball_cushion#1,1.0,1e-300",
            "line 2, column 37",
        ),
    ] {
        rejects(
            &dir,
            "scene = \"s.toml\"\nobservables = \"o.csv\"\n",
            &[scene_file, ("o.csv", &obs(row))],
            &["o.csv", at],
        );
    }
}

#[test]
fn bad_synth_requests_are_rejected_and_write_nothing() {
    let dir = temp_dir("bad-synth");
    let out = dir.join("x.toml");
    for (args, needle) in [
        (vec!["--effect", "spin_swerve=0.1"], "unknown effect"),
        (vec!["--effect", "table_slope=0.001"], "takes 2 value"),
        (vec!["--effect", "ball_restitution=1.5"], "outside"),
        (vec!["--effect", "nap_drift=abc"], "not a finite number"),
        (vec!["--fps", "0"], "fps"),
        (vec!["--noise=-1"], "noise"),
        // The data file would state a noise `snooker discrepancy` refuses.
        (vec!["--noise", "0"], "--noise 0"),
        (vec!["--noise", "0.0001"], "--noise 0.0001"),
        (vec!["--fit", "cue.colour"], "--fit cue.colour"),
        (vec!["--param", "mu_rol=0.01"], "unknown parameter"),
        // A negative value read as an unknown flag ("unexpected argument '-1'"); a camera
        // setting blamed on the scene file; the noise (mm) told in m.
        (vec!["--fps", "-10"], "--fps -10: must be in (0, 10000]"),
        (vec!["--drop", "1.5"], "--drop 1.5: must be"),
        (
            vec!["--noise", "200"],
            "--noise 200: must be in [0, 100) mm",
        ),
        // The data file listed both as the hidden truth and only the last was hidden.
        (
            vec!["--effect", "nap_drift=0.02", "--effect", "nap_drift=0.03"],
            "hidden twice",
        ),
    ] {
        let mut a = vec!["synth", "scenes/one-cushion.toml", "-o", s(&out)];
        a.extend(args);
        let o = snooker(&a);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{a:?}: {err}");
        assert!(err.contains(needle), "{needle:?} not in: {err}");
        assert!(
            std::fs::read_dir(&dir).unwrap().next().is_none(),
            "{a:?} wrote files"
        );
    }
    // A tilt cannot be hidden on a cloth without rolling resistance (resting balls would roll).
    let o = snooker(&[
        "synth",
        "scenes/one-cushion.toml",
        "--param",
        "mu_roll=0",
        "--effect",
        "table_slope=0.001,0",
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("rolling resistance"));
}

/// `-o DATA.toml` writes three files; when one of them cannot be written (a directory named
/// DATA.csv) none is, and the scene read is never replaced by the data file. Before, the scene
/// copy DATA.scene.toml was written (and a temporary DATA.csv left) before the tracks failed,
/// and `-o SCENE` overwrote the scene with the data file.
#[test]
fn synth_writes_its_three_files_or_none() {
    let dir = temp_dir("synth-three");
    std::fs::create_dir_all(dir.join("d.csv")).unwrap();
    let out = dir.join("d.toml");
    let o = snooker(&["synth", "scenes/one-cushion.toml", "-o", s(&out)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("d.csv") && err.contains("is a directory"),
        "{err}"
    );
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left, ["d.csv"], "written: {left:?}");
    let scene = dir.join("shot.toml");
    let text = std::fs::read_to_string("scenes/one-cushion.toml").unwrap();
    std::fs::write(&scene, &text).unwrap();
    let o = snooker(&["synth", s(&scene), "-o", s(&scene)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("is the scene"), "{err}");
    assert_eq!(std::fs::read_to_string(&scene).unwrap(), text);
    std::fs::remove_dir_all(&dir).ok();
}

/// The files of the report directory are checked before the workflow runs: one that cannot
/// be written (a directory of its name) stops it with exit 2 and nothing written. Before, only
/// report.json was checked: with summary.txt a directory, report.json was written, then the
/// command failed. And `--json` with `--cross-validate`, which writes no discrepancy report,
/// was ignored without a word (exit 0, no file); it is refused.
#[test]
fn the_report_directory_is_checked_before_the_run() {
    let base = [
        "discrepancy",
        "data/discrepancy/table-i.toml",
        "--model",
        "data/discrepancy/ideal-ball.toml",
        "-q",
    ];
    for blocked in ["summary.txt", "observables.png"] {
        let dir = temp_dir("report-blocked");
        std::fs::create_dir_all(dir.join(blocked)).unwrap();
        let mut a = base.to_vec();
        a.extend(["--report", s(&dir)]);
        let o = snooker(&a);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{blocked}: {err}");
        assert!(err.contains(blocked), "{err}");
        let left: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(left, [blocked], "written: {left:?}");
        std::fs::remove_dir_all(&dir).ok();
    }
    let dir = temp_dir("crossval-json");
    let json = dir.join("cv.json");
    let mut a = base.to_vec();
    a.extend(["--cross-validate", "table-i", "--json", s(&json)]);
    let o = snooker(&a);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("--json") && err.contains("--report"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// The committed synthetic example (data/discrepancy/synthetic/) is what the command the book
/// gives for it writes today (docs/discrepancy.md, "Effects hidden in synthetic data"). It had
/// gone stale: six centroids of the tracks differed in their last digit (1 um) since the
/// engine's contact detection changed.
#[test]
fn the_committed_synthetic_data_is_what_synth_writes() {
    let dir = temp_dir("synth-committed");
    let out = dir.join("slope-and-nap.toml");
    let o = snooker(&[
        "synth",
        "scenes/two-cushion.toml",
        "--effect",
        "table_slope=0.0008,0.0005",
        "--effect",
        "nap_drift=0.015",
        "--fps",
        "100",
        "--noise",
        "0.5",
        "--seed",
        "42",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in [
        "slope-and-nap.toml",
        "slope-and-nap.csv",
        "slope-and-nap.scene.toml",
    ] {
        let committed = std::fs::read_to_string(format!("data/discrepancy/synthetic/{f}")).unwrap();
        let written = std::fs::read_to_string(dir.join(f)).unwrap();
        assert!(committed == written, "{f} differs from what synth writes");
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_heading_measured_a_turn_away_is_no_gap() {
    // The one-cushion shot's cue ball leaves the cushion at -52.67 degrees; measured as
    // 307.33 (the same heading), the fit's residual was the turn between them (0), but the
    // report's observable gap and its worst observable took 360 degrees.
    let dir = temp_dir("heading-turn");
    std::fs::copy("scenes/one-cushion.toml", dir.join("s.toml")).unwrap();
    let data = dir.join("d.toml");
    std::fs::write(&data, "scene = \"s.toml\"\nobservables = \"o.csv\"\n").unwrap();
    let gap = |measured: f64| {
        std::fs::write(
            dir.join("o.csv"),
            format!("shot,ball,quantity,when,value,sigma\n,cue,heading,after:ball_cushion#1,{measured},1\n"),
        )
        .unwrap();
        let out = dir.join("r.json");
        let o = snooker(&["discrepancy", s(&data), "--json", s(&out), "-q"]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        json(&out)["baseline_observable_gap"]["max"]
            .as_f64()
            .unwrap()
    };
    let near = gap(-52.6);
    assert!(near > 0.05 && near < 0.1, "{near}");
    let turned = gap(-52.6 + 360.0);
    assert!((turned - near).abs() < 1e-9, "{turned} against {near}");
}

/// `--json -` puts the report on standard output, as `simulate --json -` does, with the
/// summary on standard error: before, it wrote a file named `-`.
#[test]
fn json_to_standard_output() {
    let dir = temp_dir("json-stdout");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_snooker"))
        .current_dir(&dir)
        .args(["discrepancy", "--json", "-", "--model"])
        .arg(std::fs::canonicalize("data/discrepancy/ideal-ball.toml").unwrap())
        .arg(std::fs::canonicalize("data/discrepancy/table-i.toml").unwrap())
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    let doc: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(doc["named"][0], "ball_friction");
    assert!(err.contains("named: ball_friction"), "{err}");
    assert!(!dir.join("-").exists(), "a file named -");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn observables_in_several_units_are_not_summed_as_one() {
    // A speed in m/s and a heading in degrees made one "RMS 10.2003 in their units", and
    // its percentage silently left the heading out.
    let dir = temp_dir("mixed-units");
    let root = std::env::current_dir().unwrap();
    let scene = root.join("scenes/table-i-1.toml");
    let rows: String = std::fs::read_to_string("data/discrepancy/table-i.csv")
        .unwrap()
        .lines()
        .filter(|l| l.starts_with("table-i-1,"))
        .map(|l| format!("{l}\n"))
        .collect();
    std::fs::write(
        dir.join("o.csv"),
        format!(
            "shot,ball,quantity,when,value,sigma\n{rows}table-i-1,red,heading,rolling:ball_ball#1,0.0,1.0\n"
        ),
    )
    .unwrap();
    std::fs::write(
        dir.join("d.toml"),
        format!(
            "observables = \"o.csv\"\n[[shots]]\nscene = {:?}\n",
            scene.display().to_string()
        ),
    )
    .unwrap();
    let o = snooker(&[
        "discrepancy",
        s(&dir.join("d.toml")),
        "--model",
        "data/discrepancy/ideal-ball.toml",
    ]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(out.contains("across mixed units (m/s, degrees"), "{out}");
    assert!(!out.contains("in their units"), "{out}");
}
