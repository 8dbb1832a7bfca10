//! The `hertz` report: contact parameters, stress maxima and the yield assessment, as text.
//!
//! Uses: the study's results and the layers below it (assess, contact, solution, stress,
//! surface, thermal), [`crate::render`]'s tables, [`crate::io`] for numbers.

pub mod coated;
pub mod commands;
pub mod hertz;
pub mod lubrication;
pub mod plastic;
pub mod probe;
pub mod rough;
pub mod surface;
pub mod sweep;
pub mod thermal;
pub mod wear;

use std::fmt::Write;

use crate::io::text;
use crate::scene::{ContactKind, Hertz, Scene};
use crate::study::assess::{Extreme, SceneMaxima};

/// A command's JSON object `text` with the heating's (`thermal --json`) added as the last key,
/// `thermal`, when there is one (`hertz --json`, `contact --json`).
pub(crate) fn with_thermal(text: String, thermal: Option<&thermal::ThermalReport>) -> String {
    match thermal {
        None => text,
        Some(thermal) => {
            let block = thermal.json().replace('\n', "\n  ");
            let body = text.trim_end().trim_end_matches('}').trim_end().to_string();
            format!("{body},\n  \"thermal\": {block}\n}}")
        }
    }
}

/// The report of a traction scene: the figure's units and the resultants of the file's
/// tractions.
fn write_tractions(out: &mut String, scene: &Scene) -> std::fmt::Result {
    let (a_m, p0_pa) = (scene.contact.half_width_m(), scene.contact.p0_pa());
    let dimensional = scene.contact.scale.is_some();
    if dimensional {
        writeln!(
            out,
            "figure units: lengths in a = {:.3} µm, stresses in p0 = {:.2} MPa; body ν = {}",
            a_m * 1e6,
            p0_pa * 1e-6,
            crate::io::text::number(scene.contact.poisson)
        )?;
    } else {
        writeln!(out, "normalised: the file gives lengths in units of a and tractions in units of p0; body ν = {}", crate::io::text::number(scene.contact.poisson))?;
    }
    let Some(grid) = &scene.tractions else {
        return Ok(());
    };
    let [ny, nx] = grid.shape();
    let [dx, dy] = grid.cell();
    let area = dx * dy;
    let (mut normal, mut shear_x, mut shear_y, mut peak) = (0.0, 0.0, 0.0, 0.0f64);
    for row in 0..ny {
        for column in 0..nx {
            let (p, qx, qy) = grid.traction(row, column);
            normal += p * area;
            shear_x += qx * area;
            shear_y += qy * area;
            peak = peak.max(p);
        }
    }
    writeln!(
        out,
        "traction grid                {nx} x {ny} cells of {dx:.4} a x {dy:.4} a"
    )?;
    if dimensional {
        let force = p0_pa * a_m * a_m;
        writeln!(
            out,
            "resultant normal force       P  = {:.4} N",
            normal * force
        )?;
        writeln!(
            out,
            "resultant tangential forces  Qx = {:.4} N, Qy = {:.4} N",
            shear_x * force,
            shear_y * force
        )?;
        writeln!(
            out,
            "largest pressure             {:.2} MPa",
            peak * p0_pa * 1e-6
        )?;
    } else {
        writeln!(out, "resultant normal force       P  = {normal:.6} p0 a²")?;
        writeln!(
            out,
            "resultant tangential forces  Qx = {shear_x:.6} p0 a², Qy = {shear_y:.6} p0 a²"
        )?;
        writeln!(out, "largest pressure             {peak:.4} p0")?;
    }
    Ok(())
}

/// Formats the report of a scene (first panel's friction and Poisson ratio are the scene's)
/// with its stress maxima as the study found them
/// ([`crate::study::assess::scene_maxima`]).
pub fn hertz(scene: &Scene, maxima: &SceneMaxima) -> String {
    let mut out = String::new();
    // Writing into a String cannot fail.
    let _ = write_report(&mut out, scene, maxima);
    if let Some(lubrication) = crate::study::lubrication::films(scene) {
        out.push_str(&lubrication::text(&lubrication));
    }
    out
}

/// Positions of maxima closer to zero than this (units of a) are zero: the compass search of
/// [`crate::study::assess::maximum`] places a smooth maximum to about 1e-8 a, so an on-axis
/// maximum lands a few 1e-9 a off the axis, which would print as `x = 8.4564e-10 mm`.
const POSITION_RESOLUTION_OVER_A: f64 = 1e-6;

/// `value_over_a`, or 0 within [`POSITION_RESOLUTION_OVER_A`] of it.
pub(crate) fn snap_position(value_over_a: f64) -> f64 {
    if value_over_a.abs() < POSITION_RESOLUTION_OVER_A {
        0.0
    } else {
        value_over_a
    }
}

fn mm(m: f64) -> String {
    format!("{} mm", text::fixed(m * 1e3, 4))
}

fn write_report(out: &mut String, scene: &Scene, maxima: &SceneMaxima) -> std::fmt::Result {
    let contact = &scene.contact;
    writeln!(out, "scene {}", scene.name)?;
    let point = contact.kind != ContactKind::Line;
    let geometry = match contact.kind {
        ContactKind::Point if contact.tangential.is_some() => {
            "point (a sphere in Cattaneo-Mindlin partial slip, contact circle of radius a)"
        }
        ContactKind::Point => {
            "point (two spheres or a sphere on a flat, contact circle of radius a)"
        }
        ContactKind::Elliptical => {
            "elliptical (two principal radii per body; semi-axes a along x, b along y)"
        }
        ContactKind::Line => "line (two cylinders, plane strain)",
        ContactKind::Rough => "rough (a rough surface pressed on a flat, pressure solved)",
        ContactKind::Surface => "a rough surface (no contact solved)",
        ContactKind::Tractions => "surface tractions read from a CSV grid ([tractions])",
    };
    if contact.kind == ContactKind::Tractions {
        writeln!(out, "contact: {geometry}")?;
        write_tractions(out, scene)?;
        return write_maxima(out, scene, maxima);
    }
    writeln!(
        out,
        "contact: {geometry}; friction μ = {} (q = μ p on body 1 in +x, trailing edge at x = -a)",
        crate::io::text::number(contact.friction)
    )?;
    let a_name = if point {
        "contact radius              "
    } else {
        "contact half-width          "
    };
    match (contact.dimensional, contact.scale) {
        (None, None) => {
            writeln!(
                out,
                "normalised contact: lengths in units of a, stresses in units of p0; body 1 ν = {}",
                crate::io::text::number(contact.poisson)
            )?;
        }
        (None, Some(scale)) => {
            writeln!(
                out,
                "contact given by its size; body 1 ν = {}",
                crate::io::text::number(contact.poisson)
            )?;
            let (a, p0) = (scale.half_width_m, scale.p0_pa);
            writeln!(out, "{a_name} a  = {} µm", text::fixed(a * 1e6, 3))?;
            writeln!(
                out,
                "peak pressure                p0 = {} MPa",
                text::fixed(p0 * 1e-6, 2)
            )?;
            if point {
                writeln!(
                    out,
                    "mean pressure                pm = {} MPa (= 2 p0 / 3)",
                    text::fixed(2.0 / 3.0 * p0 * 1e-6, 2)
                )?;
                writeln!(
                    out,
                    "load                         W  = {} N (= 2 π a² p0 / 3)",
                    text::fixed(2.0 / 3.0 * std::f64::consts::PI * a * a * p0, 4)
                )?;
            } else {
                writeln!(
                    out,
                    "mean pressure                pm = {} MPa (= π p0 / 4)",
                    text::fixed(std::f64::consts::FRAC_PI_4 * p0 * 1e-6, 2)
                )?;
                writeln!(
                    out,
                    "load per unit length         P  = {} kN/m (= π a p0 / 2)",
                    text::fixed(std::f64::consts::FRAC_PI_2 * a * p0 * 1e-3, 4)
                )?;
            }
        }
        (Some(d), _) => {
            if let Some(g) = d.gears {
                writeln!(
                    out,
                    "spur gears: module {}, teeth {} and {}, pressure angle {} deg",
                    mm(g.module_m),
                    g.teeth[0],
                    g.teeth[1],
                    text::fixed(g.pressure_angle_rad.to_degrees(), 2)
                )?;
                writeln!(
                    out,
                    "  pitch radii                 r1 = {}, r2 = {}",
                    mm(g.pitch_radius_m(0)),
                    mm(g.pitch_radius_m(1))
                )?;
                writeln!(
                    out,
                    "  base radii                  rb1 = {}, rb2 = {}",
                    mm(g.base_radius_m(0)),
                    mm(g.base_radius_m(1))
                )?;
                writeln!(
                    out,
                    "  flank radii at pitch point  R1 = r1 sin φ = {}, R2 = r2 sin φ = {}",
                    mm(g.curvature_radius_at_pitch_point_m(0)),
                    mm(g.curvature_radius_at_pitch_point_m(1))
                )?;
            }
            for (name, body) in [("body 1", d.body1), ("body 2", d.body2)] {
                let radius = if body.radius_m.is_nan() {
                    "(principal radii in the scene)".to_string()
                } else if body.radius_m.is_infinite() {
                    "flat".to_string()
                } else {
                    mm(body.radius_m)
                };
                if body.material.modulus_pa.is_infinite() {
                    // A rigid indenter ([plasticity] scenes): nothing of it enters E*.
                    writeln!(out, "{name}: radius {radius}, rigid")?;
                    continue;
                }
                writeln!(
                    out,
                    "{name}: radius {radius}, E = {} GPa, ν = {}",
                    text::fixed(body.material.modulus_pa * 1e-9, 1),
                    crate::io::text::number(body.material.poisson)
                )?;
            }
            match d.hertz {
                Hertz::Elliptical(ellipse) => {
                    let c = ellipse.curvature;
                    writeln!(
                        out,
                        "load                         W  = {} N",
                        text::fixed(ellipse.load_n, 4)
                    )?;
                    writeln!(
                        out,
                        "effective modulus            E* = {} GPa",
                        text::fixed(ellipse.effective_modulus_pa * 1e-9, 3)
                    )?;
                    writeln!(
                        out,
                        "relative radii               Rx = {}, Ry = {} (gap x²/(2Rx) + y²/(2Ry))",
                        mm(0.5 / c.half_curvature_x_per_m),
                        mm(0.5 / c.half_curvature_y_per_m)
                    )?;
                    writeln!(
                        out,
                        "semi-axes                    a  = {} µm along x, b = {} µm along y (b/a = {})",
                        text::fixed(ellipse.semi_axis_x_m * 1e6, 3),
                        text::fixed(ellipse.semi_axis_y_m * 1e6, 3),
                        text::fixed(ellipse.semi_axis_y_m / ellipse.semi_axis_x_m, 4)
                    )?;
                    writeln!(
                        out,
                        "eccentricity                 e  = {}",
                        text::fixed(ellipse.eccentricity, 5)
                    )?;
                    writeln!(
                        out,
                        "peak pressure                p0 = {} MPa",
                        text::fixed(ellipse.p0_pa * 1e-6, 2)
                    )?;
                    writeln!(
                        out,
                        "mean pressure                pm = {} MPa (= 2 p0 / 3)",
                        text::fixed(ellipse.mean_pressure_pa * 1e-6, 2)
                    )?;
                    writeln!(
                        out,
                        "approach                     δ  = {} µm",
                        text::fixed(ellipse.approach_m * 1e6, 4)
                    )?;
                }
                Hertz::Line(line) => {
                    writeln!(
                        out,
                        "load per unit length         P  = {} kN/m",
                        text::fixed(line.load_n_per_m * 1e-3, 4)
                    )?;
                    writeln!(
                        out,
                        "effective modulus            E* = {} GPa",
                        text::fixed(line.effective_modulus_pa * 1e-9, 3)
                    )?;
                    writeln!(
                        out,
                        "effective radius             R  = {}",
                        mm(line.effective_radius_m)
                    )?;
                    writeln!(
                        out,
                        "{a_name} a  = {} µm",
                        text::fixed(line.half_width_m * 1e6, 3)
                    )?;
                    writeln!(
                        out,
                        "peak pressure                p0 = {} MPa",
                        text::fixed(line.p0_pa * 1e-6, 2)
                    )?;
                    writeln!(
                        out,
                        "mean pressure                pm = {} MPa (= π p0 / 4)",
                        text::fixed(line.mean_pressure_pa * 1e-6, 2)
                    )?;
                    match line.approach_of_axes_m(&d.body1, &d.body2) {
                        Some(delta) => writeln!(
                            out,
                            "approach of the axes         δ  = {} µm (two cylinders: Σ P (1 − ν²)/(π E) (2 ln(4R/a) − 1), Johnson 1985 ch. 5)",
                            text::fixed(delta * 1e6, 4)
                        )?,
                        None => writeln!(out, "approach                     not defined by a 2-D line contact with a flat or concave body (it depends on the bodies' size)")?,
                    }
                }
                Hertz::Point(point) => {
                    writeln!(
                        out,
                        "load                         W  = {} N",
                        text::fixed(point.load_n, 4)
                    )?;
                    writeln!(
                        out,
                        "effective modulus            E* = {} GPa",
                        text::fixed(point.effective_modulus_pa * 1e-9, 3)
                    )?;
                    writeln!(
                        out,
                        "effective radius             R  = {}",
                        mm(point.effective_radius_m)
                    )?;
                    writeln!(
                        out,
                        "{a_name} a  = {} µm",
                        text::fixed(point.radius_m * 1e6, 3)
                    )?;
                    writeln!(
                        out,
                        "peak pressure                p0 = {} MPa",
                        text::fixed(point.p0_pa * 1e-6, 2)
                    )?;
                    writeln!(
                        out,
                        "mean pressure                pm = {} MPa (= 2 p0 / 3)",
                        text::fixed(point.mean_pressure_pa * 1e-6, 2)
                    )?;
                    writeln!(
                        out,
                        "approach                     δ  = {} µm (= a² / R)",
                        text::fixed(point.approach_m * 1e6, 4)
                    )?;
                }
            }
        }
    }
    write_maxima(out, scene, maxima)
}

/// The stress maxima and the yield check, as the study found them
/// ([`crate::study::assess::scene_maxima`]).
fn write_maxima(out: &mut String, scene: &Scene, found: &SceneMaxima) -> std::fmt::Result {
    let contact = &scene.contact;
    let point = contact.kind != ContactKind::Line;
    let a_m = contact.half_width_m();
    let p0_pa = contact.p0_pa();
    let maxima = match (&found.maxima, found.grid) {
        (Ok(maxima), None) => *maxima,
        (Ok(maxima), Some([nx, ny])) => {
            writeln!(out, "stress maxima by DC-FFT at the cell centres of the {nx} x {ny} traction grid, depth step one cell (no closed form for this contact):")?;
            if maxima.yield_starts_at_surface() {
                writeln!(out, "note: a surface peak at a contact edge converges slowly with the grid (a sphere sliding with μ = 0.4: 6.5 % low on 127² cells, 4 % on 511²); raise [numerical] cells to check")?;
            }
            *maxima
        }
        (Err(e), _) => {
            writeln!(out, "stress maxima: not computed ({e})")?;
            return Ok(());
        }
    };
    let dimensional = contact.scale.is_some();
    let describe = |e: &Extreme| {
        let (x, y, z) = (
            snap_position(e.x_over_a),
            snap_position(e.y_over_a),
            snap_position(e.z_over_a),
        );
        let mut text = format!("{:.4} p0", e.value_over_p0);
        if dimensional {
            let _ = write!(
                text,
                " = {} MPa",
                text::fixed(e.value_over_p0 * p0_pa * 1e-6, 1)
            );
        }
        if point {
            let _ = write!(
                text,
                " at x = {x:.3} a, y = {}{y:.3} a, z = {z:.3} a",
                if e.mirrored_in_y && y != 0.0 {
                    "±"
                } else {
                    ""
                },
            );
        } else {
            let _ = write!(text, " at x = {x:.3} a, z = {z:.3} a");
        }
        if dimensional {
            let _ = write!(text, " (x = {}, z = {})", mm(x * a_m), mm(z * a_m));
        }
        text
    };
    let body = if contact.kind == ContactKind::Tractions {
        "the body"
    } else {
        "body 1"
    };
    writeln!(
        out,
        "stress maxima in {body} (ν = {}):",
        crate::io::text::number(contact.poisson)
    )?;
    writeln!(
        out,
        "  von Mises σvM                {}",
        describe(&maxima.von_mises)
    )?;
    writeln!(
        out,
        "  maximum shear (σ1 − σ3)/2    {}",
        describe(&maxima.max_shear)
    )?;
    if let (false, Some(tau1)) = (point, &found.tau1) {
        writeln!(out, "  principal shear τ1 (xz)      {}", describe(tau1))?;
    }
    writeln!(
        out,
        "  von Mises on the surface     {}",
        describe(&maxima.von_mises_surface)
    )?;
    let starts = if maxima.yield_starts_at_surface() {
        "at the surface"
    } else {
        "below the surface"
    };
    let vm = maxima.von_mises.value_over_p0;
    let tresca = maxima.max_shear.value_over_p0;
    let tractions = contact.kind == ContactKind::Tractions;
    if tractions {
        // The tractions' unit is not a Hertz peak pressure: no p0 at first yield.
        writeln!(
            out,
            "first yield (von Mises) starts {starts}, at z = {:.3} a",
            maxima.von_mises.z_over_a
        )?;
    } else {
        writeln!(out, "first yield (von Mises) starts {starts}, at z = {:.3} a, when p0 = {:.3} Y (Tresca: p0 = {:.3} Y)", maxima.von_mises.z_over_a, 1.0 / vm, 0.5 / tresca)?;
    }
    let (Some(y), true) = (scene.yield_strength(), dimensional) else {
        if dimensional {
            writeln!(out, "yield strength not given: add contact.yield_strength or contact.hardness for a yield check")?;
        }
        return Ok(());
    };
    match y.from_hardness {
        Some(h) => writeln!(out, "yield strength               Y  = {:.0} MPa (from {} {}: H = {:.0} MPa, Y = H/3, Tabor 1951)", y.pa * 1e-6, crate::io::text::number(h), y.hardness_scale, h * 9.80665)?,
        None if contact.yield_strength.is_none() => writeln!(out, "yield strength               Y  = {:.0} MPa (plasticity.yield_strength)", y.pa * 1e-6)?,
        None => writeln!(out, "yield strength               Y  = {:.0} MPa", y.pa * 1e-6)?,
    }
    let ratio_vm = vm * p0_pa / y.pa;
    let ratio_tresca = tresca * p0_pa / (0.5 * y.pa);
    let surface_ratio = maxima.von_mises_surface.value_over_p0 * p0_pa / y.pa;
    writeln!(out, "  σvM,max / Y                  {ratio_vm:.3}")?;
    writeln!(out, "  τmax / (Y/2) (Tresca)        {ratio_tresca:.3}")?;
    writeln!(out, "  surface σvM,max / Y          {surface_ratio:.3}")?;
    let verdict = if ratio_vm < 1.0 {
        "no yield: the contact is fully elastic".to_string()
    } else if surface_ratio < 1.0 {
        "yield in the subsurface only: the plastic zone is contained below an elastic surface layer"
            .to_string()
    } else {
        "yield reaches the surface: surface plastic flow has been initiated".to_string()
    };
    writeln!(out, "  verdict                      {verdict}")?;
    // The field scales with p0, and P ∝ p0² (line contact) or W ∝ p0³ (point contact), so
    // first yield is at p0 = Y / σvM,max.
    let p0_yield = y.pa / vm;
    if tractions {
        // Stresses are linear in the tractions.
        return writeln!(
            out,
            "  first yield                  when every traction is multiplied by {:.2}",
            p0_yield / p0_pa
        );
    }
    let load_factor = (p0_yield / p0_pa).powi(if point { 3 } else { 2 });
    match contact.dimensional {
        Some(d) => {
            let load = d.hertz.load_for_peak_pressure(p0_yield);
            let load_text = match d.hertz {
                Hertz::Line(_) => format!("P_Y = {:.3} kN/m", load * 1e-3),
                Hertz::Point(_) | Hertz::Elliptical(_) => format!("W_Y = {load:.3} N"),
            };
            writeln!(
                out,
                "  load at first yield          {load_text} (p0 = {:.1} MPa; load factor {:.2})",
                p0_yield * 1e-6,
                load_factor
            )?
        }
        None => writeln!(
            out,
            "  first yield                  at p0 = {:.1} MPa (load factor {load_factor:.2} at the same geometry)",
            p0_yield * 1e-6
        )?,
    }
    Ok(())
}
