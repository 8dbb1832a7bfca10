//! `probe`: the stress at given points of a scene.

use std::io::BufRead;

use anyhow::{bail, Context, Result};

use super::args::{ContactArg, MethodArg, ProbeArgs};
use super::console::with_stdout;
use stressfield::io::text;
use stressfield::scene::{ContactKind, Method, PanelSpec};
use stressfield::solution::Solution;
use stressfield::study;

pub(super) fn probe_command(args: &ProbeArgs) -> Result<()> {
    let ProbeArgs {
        scene,
        contact,
        friction,
        poisson,
        method,
        strips,
        cells,
        extent,
        points,
    } = args;
    let (scene, contact, friction, poisson) = (scene.as_deref(), *contact, *friction, *poisson);
    let (method, strips, cells, extent) = (*method, *strips, *cells, *extent);
    let points = points.as_path();
    if !(1..=1_000_000).contains(&strips) {
        bail!("--strips must lie in 1..=1000000, got {strips}");
    }
    let (mut mu, mut nu, mut kind) = (0.0, 0.3, ContactArg::Line);
    let mut loaded = None;
    if let Some(path) = scene {
        let scene = stressfield::study::load_scene(path)?;
        if scene.contact.coating.is_some() {
            anyhow::bail!("contact.body1.coating: probe evaluates the homogeneous closed forms, not a coated body\nhint: `stressfield hertz {}` reports the coated body's stresses", path.display());
        }
        (mu, nu) = (scene.contact.friction, scene.contact.poisson);
        kind = match scene.contact.kind {
            ContactKind::Line => ContactArg::Line,
            ContactKind::Point | ContactKind::Elliptical | ContactKind::Tractions => {
                ContactArg::Point
            }
            ContactKind::Rough | ContactKind::Surface => bail!(
                "probe takes Hertz and traction scenes; {} is a rough or surface scene\nhint: `stressfield contact {}` solves it and writes its pressure; `render` draws the stresses under it",
                path.display(),
                path.display()
            ),
        };
        if let Some(given) = contact.filter(|c| *c != kind) {
            bail!(
                "--contact {} contradicts the scene {}, a {} contact\nhint: drop --contact; the scene decides",
                if given == ContactArg::Line { "line" } else { "point" },
                path.display(),
                if kind == ContactArg::Line { "line" } else { "point" }
            );
        }
        loaded = Some(scene);
    } else if let Some(given) = contact {
        kind = given;
    }
    if !(8..=2048).contains(&cells) {
        bail!("--cells must lie in 8..=2048, got {cells}");
    }
    if !(extent.is_finite() && (1.0..=20.0).contains(&extent)) {
        bail!(
            "--extent must lie in 1..=20 (units of a; the grid must cover the contact), got {}",
            text::number(extent)
        );
    }
    if let Some(f) = friction {
        if let Some(message) = stressfield::scene::friction_requirement(f) {
            bail!(
                "--friction: {message}\nhint: {}",
                stressfield::scene::FRICTION_HINT
            );
        }
        mu = f;
    }
    if let Some(p) = poisson {
        if !(p > -1.0 && p <= 0.5) {
            bail!("--poisson must lie in (-1, 0.5], got {}", text::number(p));
        }
        nu = p;
    }
    let input: Box<dyn BufRead> = if points.as_os_str() == "-" {
        Box::new(std::io::stdin().lock())
    } else {
        let file = std::fs::File::open(points)
            .with_context(|| format!("cannot open the points file {}", points.display()))?;
        Box::new(std::io::BufReader::new(file))
    };
    let rows = stressfield::io::points::read_points(input).with_context(|| {
        format!(
            "in the points {}",
            if points.as_os_str() == "-" {
                "from standard input".into()
            } else {
                format!("file {}", points.display())
            }
        )
    })?;
    // A scene's contact may have no closed form (elliptical, partial slip, a traction file):
    // then its numerical method, with the scene's grid.
    let solution = match (loaded, kind, method) {
        (Some(scene), _, _) => {
            let panel = PanelSpec {
                method: match method {
                    MethodArg::ClosedForm => Method::ClosedForm,
                    MethodArg::Numerical => Method::Numerical,
                },
                friction: mu,
                poisson: nu,
                // Probed at points, not on a section.
                section: scene.figure.section,
                at: 0.0,
                subtitle: None,
            };
            match (scene.contact.kind, method) {
                (ContactKind::Line, MethodArg::Numerical) => {
                    Solution::line_numerical(mu, nu, strips)
                }
                _ => study::solution(&scene, &panel)?,
            }
        }
        (None, ContactArg::Line, MethodArg::ClosedForm) => Solution::LineHertz {
            friction: mu,
            poisson: nu,
        },
        (None, ContactArg::Line, MethodArg::Numerical) => Solution::line_numerical(mu, nu, strips),
        (None, ContactArg::Point, MethodArg::ClosedForm) => Solution::SphereHertz {
            friction: mu,
            poisson: nu,
        },
        (None, ContactArg::Point, MethodArg::Numerical) => {
            Solution::sphere_numerical(mu, nu, cells, extent)?
        }
    };
    with_stdout(|mut out| stressfield::report::probe::write_csv(&mut out, &solution, &rows))
}
