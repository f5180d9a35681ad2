//! `--line-budget` in `qsic motion` and `qsic contact`: a line over its budget is the budget's
//! error line between answered lines, in order; a single query over it fails with the
//! budget's message.

#[path = "common/run.rs"]
mod run;

use run::qsic;
use std::process::Output;

fn lines(out: &Output) -> Vec<serde_json::Value> {
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// Two sphere motions (below 2·10⁵ units for motion, 5·10⁵ for contact) around a screw
/// motion of two ellipsoids (between 10⁶ and 2·10⁶ for motion, more for contact).
const BATCH: &str = r#"{"id":1,"A":"x^2+y^2+z^2-4","B":"(x-t)^2+y^2+z^2-1"}
{"id":2,"A":{"quadric":"x^2/4+y^2+z^2/9-1","rotate":{"axis":[0,0,1]},"translate":[0,0,"t"]},"B":"(x-3)^2/9+(y-1)^2/4+(z-1/2)^2-1"}
{"id":3,"A":"x^2+y^2+z^2-4","B":"(x-2*t)^2+y^2+z^2-1"}
"#;

#[test]
fn a_motion_line_over_its_budget_is_an_error_between_answered_lines() {
    for command in ["motion", "contact"] {
        let out = qsic(&[command, "--line-budget", "1e6", "--batch", "-"], BATCH);
        assert_eq!(out.status.code(), Some(1), "{command}: an error line");
        let got = lines(&out);
        let ids: Vec<i64> = got.iter().map(|v| v["id"].as_i64().unwrap()).collect();
        assert_eq!(ids, [1, 2, 3], "{command}");
        assert!(got[0].get("error").is_none(), "{command}: {}", got[0]);
        assert!(got[2].get("error").is_none(), "{command}: {}", got[2]);
        let message = got[1]["error"]["message"].as_str().unwrap();
        assert!(
            message.contains("over the work budget: 1000000 units"),
            "{command}: {message}"
        );
        // the default budget answers every line
        let out = qsic(&[command, "--batch", "-"], BATCH);
        assert_eq!(out.status.code(), Some(0), "{command}");
        assert!(lines(&out).iter().all(|v| v.get("error").is_none()));
    }
}

#[test]
fn a_single_motion_over_its_budget_fails_with_the_budget_message() {
    for command in ["motion", "contact"] {
        let out = qsic(
            &[
                command,
                "--line-budget",
                "1000",
                "x^2+y^2+z^2-4",
                "(x-t)^2+y^2+z^2-1",
            ],
            "",
        );
        assert_eq!(out.status.code(), Some(1), "{command}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("over the work budget: 1000 units"),
            "{command}: {err}"
        );
    }
}
