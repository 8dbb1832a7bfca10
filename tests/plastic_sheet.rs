//! The elastic-plastic point contact's `hertz` yield assessment, render sheet and recording
//! (issue 51).

use crate::cli::{run, stderr};

/// `hertz` of a `[plasticity]` scene assesses yield against `plasticity.yield_strength` (it
/// read `contact.yield_strength` only and reported "yield strength not given").
#[test]
fn hertz_of_a_plastic_scene_uses_the_plasticity_yield_strength() {
    let scene = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/plastic_rigid_ball_on_flat.toml"
    );
    let output = run(&["hertz", scene, "--json"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).expect("one JSON object");
    assert_eq!(json["yield_strength_pa"], 1e9);
    // p0 = 2.5 Y and σvM,max = 0.6200 p0 (Hamilton's closed form on the axis): 1.550 Y.
    let ratio = json["von_mises_over_yield"].as_f64().expect("a number");
    assert!((ratio - 2.5 * 0.62).abs() < 2e-3, "σvM/Y = {ratio}");
    assert_eq!(json["verdict"], "subsurface");
    // First yield at p0 = Y / 0.6200: the load scales as p0³.
    let load = json["load_at_first_yield"].as_f64().expect("a number");
    let expected = 151.62 * (1.0 / (0.620 * 2.5f64)).powi(3);
    assert!(
        (load / expected - 1.0).abs() < 1e-3,
        "{load} N, {expected} N"
    );
    let text = run(&["hertz", scene]);
    assert!(text.status.success(), "{}", stderr(&text));
    let text = String::from_utf8_lossy(&text.stdout).into_owned();
    assert!(
        text.contains("Y  = 1000 MPa (plasticity.yield_strength)"),
        "{text}"
    );
    assert!(!text.contains("yield strength not given"), "{text}");
}
