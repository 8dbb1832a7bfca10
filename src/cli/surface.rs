//! `contact` and `surface`: a rough contact solved and reported, a surface characterised.

use std::path::Path;

use anyhow::{anyhow, bail, Context, Result};

use super::args::SurfaceArgs;
use super::console::{print_out, StudyBars};
use super::npy::{npy_bytes, npy_path, write_npy, Reserved};
use stressfield::io::output::Staged;
use stressfield::io::units::{self, Dimension};
use stressfield::report::rough::ContactReport;
use stressfield::report::surface::SurfaceReport;
use stressfield::scene::{ContactKind, Scene};
use stressfield::study;
use stressfield::study::commands::ContactStudy;
use stressfield::surface::read::{self, Fill, ReadOptions};
use stressfield::surface::stats::{self, Characterisation, FormRemoval, Options};
use stressfield::surface::MIN_SPACING_M;

/// `contact SCENE [--json] [--pressure FILE.npy]`.
pub fn contact(scene_path: &Path, json: bool, pressure: Option<&Path>) -> Result<()> {
    let scene = stressfield::study::load_scene(scene_path)?;
    if scene.contact.kind != ContactKind::Rough {
        bail!(
            "{} is not a rough contact scene (contact.kind = \"rough\")\nhint: `stressfield hertz {}` reports Hertz contacts",
            scene_path.display(),
            scene_path.display()
        );
    }
    if let Some(path) = pressure {
        npy_path("--pressure", path)?;
    }
    // Reserved before the solve: a missing directory is said at once (issue 42, class 6).
    let mut staged = Staged::new();
    let pressure_file = pressure
        .map(|path| Reserved::new(&mut staged, path))
        .transpose()?;
    // The study the Python package's `Scene.contact` runs too (issue 50).
    let mut bars = StudyBars::new(&scene);
    let study = study::commands::contact(&scene, &mut |p| bars.show(p));
    bars.finish(study.as_ref().ok().map(|s| s.solution.iterations));
    let study = study?;
    if let Some(file) = &pressure_file {
        file.fill(&npy_bytes(&study.solution.pressure_pa, "pressure")?)?;
    }
    staged.commit()?;
    if json {
        let text = stressfield::report::commands::contact_json(&scene, &study);
        print_out(&format!("{text}\n"))
    } else {
        let mut text = contact_text(&scene, &study);
        if let Some(path) = pressure {
            text.push_str(&format!(
                "pressure written to {} (Pa, float64, [rows, columns], row = y)\n",
                path.display()
            ));
        }
        print_out(&text)
    }
}

/// The readable report of a rough scene's contact (`contact`, and `hertz` of a rough scene):
/// the contact, then the heating's block.
pub(crate) fn contact_text(scene: &Scene, study: &ContactStudy) -> String {
    let report = ContactReport::new(scene, &study.solution, &study.findings);
    let mut text = report.text(scene);
    if let Some(heating) = &study.heating {
        if heating.coupled.is_some() {
            text.push_str("(the contact above is the isothermal one; the heated contact of the coupled solution follows in the heating block, whose temperatures and stresses are its own)\n");
        }
        text.push_str(&stressfield::report::thermal::ThermalReport::new(heating).text(heating));
    }
    text
}

/// The readable characterisation of a surface scene (`hertz` of a surface scene), as
/// `surface SCENE` prints it.
pub(crate) fn surface_scene_text(scene: &Scene, characterisation: &Characterisation) -> String {
    let rough = scene.contact.rough;
    let source = scene.surface.as_ref().map_or("", |s| s.source.as_str());
    SurfaceReport::new(
        characterisation,
        rough.and_then(|r| r.e_star_pa),
        rough.and_then(|r| r.hardness_pa),
    )
    .text(characterisation, source)
}

/// A length flag (`--spacing 1e-6m`, `--band 4um,100um`), read as scenes read lengths.
fn length(flag: &str, text: &str) -> Result<f64> {
    let metres = units::parse(text, Dimension::Length).map_err(|m| anyhow!("{flag}: {m}"))?;
    // The spacings and wavelengths of a surface (as in scenes): from an atomic spacing to 10 km.
    if !((MIN_SPACING_M..=1e4).contains(&metres)) {
        bail!(
            "{flag} must lie between 1e-10 m and 10000 m, got {}",
            stressfield::io::text::cut(text.trim(), 40)
        );
    }
    Ok(metres)
}

/// A modulus (`--e-star 115GPa`), or with `hardness` a pressure or a hardness number
/// (`--hardness 3GPa`, `1e3HV`: kgf/mm², times 9.80665 MPa), read as scenes read them.
fn pressure_pa(flag: &str, text: &str, hardness: bool) -> Result<f64> {
    let pa = if hardness {
        units::hardness_pa(text)
    } else {
        units::parse(text, Dimension::Pressure)
    }
    .map_err(|m| anyhow!("{flag}: {m}"))?;
    // As moduli, hardnesses and pressures in scenes: a pascal to ten times diamond's modulus.
    if !((1.0..=1e13).contains(&pa)) {
        bail!(
            "{flag} must lie between 1 Pa and 1e13 Pa, got {}",
            stressfield::io::text::cut(text.trim(), 40)
        );
    }
    Ok(pa)
}

/// `surface FILE|SCENE`.
pub fn surface(args: &SurfaceArgs) -> Result<()> {
    let form = match args.form.as_str() {
        "plane" => FormRemoval::Plane,
        "quadratic" => FormRemoval::Quadratic,
        other => bail!("--form {other}: use plane or quadratic"),
    };
    let band_m = args
        .band
        .as_deref()
        .map(|text| -> Result<(f64, f64)> {
            let (a, b) = text
                .split_once(',')
                .context("--band takes two wavelengths, e.g. 4um,100um")?;
            let (a, b) = (length("--band", a)?, length("--band", b)?);
            if a >= b {
                bail!("--band: give the shorter wavelength first, got {text}");
            }
            Ok((a, b))
        })
        .transpose()?;
    if let Some(path) = &args.heights {
        npy_path("--heights", path)?;
    }
    let is_scene = args.input.extension().is_some_and(|e| e == "toml");
    let (map, source, generated, mut e_star, mut hardness, scene_form, scene_band) = if is_scene {
        for (flag, given) in [
            ("--spacing", args.spacing.is_some()),
            ("--height-unit", args.height_unit.is_some()),
            ("--length-unit", args.length_unit.is_some()),
        ] {
            if given {
                bail!(
                    "{flag} is for a height file; the scene {} gives its own",
                    args.input.display()
                );
            }
        }
        let scene = stressfield::study::load_scene(&args.input)?;
        let Some(surface) = &scene.surface else {
            bail!(
                "{} has no [surface]: characterise a surface scene (kind = \"surface\" or \"rough\") or a height file",
                args.input.display()
            );
        };
        let rough = scene.contact.rough;
        (
            surface.body1.as_ref().clone(),
            surface.source.clone(),
            surface.generated,
            rough.and_then(|r| r.e_star_pa),
            rough.and_then(|r| r.hardness_pa),
            Some(surface.form),
            surface.band_m,
        )
    } else {
        let spacing_m = args
            .spacing
            .as_deref()
            .map(|text| -> Result<[f64; 2]> {
                match text.split_once(',') {
                    Some((x, y)) => Ok([length("--spacing", x)?, length("--spacing", y)?]),
                    None => {
                        let d = length("--spacing", text)?;
                        Ok([d, d])
                    }
                }
            })
            .transpose()?;
        let unit = |flag: &str, value: &Option<String>| -> Result<Option<f64>> {
            value
                .as_deref()
                .map(|text| {
                    read::length_unit_m(text).with_context(|| {
                        format!(
                            "{flag} {}: use one of {}",
                            stressfield::io::text::cut(text, 40),
                            Dimension::Length.unit_list()
                        )
                    })
                })
                .transpose()
        };
        let fill = match args.fill.as_str() {
            "refuse" => Fill::Refuse,
            "interpolate" => Fill::Interpolate,
            other => bail!("--fill {other}: use refuse or interpolate"),
        };
        let options = ReadOptions {
            spacing_m,
            height_unit_m: unit("--height-unit", &args.height_unit)?,
            xyz_length_unit_m: unit("--length-unit", &args.length_unit)?,
            fill,
        };
        let map = read::read_surface(&args.input, &options)?;
        (
            map,
            args.input.display().to_string(),
            false,
            None,
            None,
            None,
            None,
        )
    };
    if let Some(text) = &args.e_star {
        e_star = Some(pressure_pa("--e-star", text, false)?);
    }
    if let Some(text) = &args.hardness {
        hardness = Some(pressure_pa("--hardness", text, true)?);
    }
    let options = Options {
        form: if args.form == "plane" {
            scene_form.unwrap_or(form)
        } else {
            form
        },
        band_m: band_m.or(scene_band),
        window: !generated,
    };
    let characterisation =
        stats::characterise(&map, &options).with_context(|| format!("characterising {source}"))?;
    let report = SurfaceReport::new(&characterisation, e_star, hardness);
    if let Some(path) = &args.heights {
        write_npy(path, map.heights_m(), "heights")?;
    }
    if args.json {
        print_out(&format!("{}\n", report.json()))
    } else {
        let mut text = report.text(&characterisation, &source);
        if let Some(path) = &args.heights {
            text.push_str(&format!(
                "heights written to {} (m, float64, [rows, columns], row = y, before levelling)\n",
                path.display()
            ));
        }
        print_out(&text)
    }
}
