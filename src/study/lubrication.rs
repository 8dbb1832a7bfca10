//! The film thickness and λ of a lubricated scene (`[lubricant]`): the standard regressions on
//! the scene's Hertz contact (Pan & Hamrock for a line contact, Hamrock & Dowson for a point or
//! elliptical one), and for spur gears along the path of contact, each point with its flank
//! radii, its share of the load and its flanks' entrainment speed (as the frictional heating
//! takes them, [`crate::study::gear_heating`]).

use crate::contact::{effective_modulus, Body, LineContact};
use crate::lubrication::film::{
    hamrock_dowson, pan_hamrock, validity, FilmConditions, FilmValidity, Films,
};
use crate::lubrication::{lambda_ratio, Regime};
use crate::scene::{Hertz, LubricantSpec, Scene};

/// Which regression gave the film.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FilmFormula {
    /// Pan & Hamrock (1989), line contacts.
    PanHamrock,
    /// Hamrock & Dowson (1977), point and elliptical contacts.
    HamrockDowson,
}

impl FilmFormula {
    /// `pan_hamrock_1989` or `hamrock_dowson_1977`.
    pub fn key(self) -> &'static str {
        match self {
            FilmFormula::PanHamrock => "pan_hamrock_1989",
            FilmFormula::HamrockDowson => "hamrock_dowson_1977",
        }
    }

    /// The citation, for reports.
    pub fn citation(self) -> &'static str {
        match self {
            FilmFormula::PanHamrock => "Pan & Hamrock 1989, line contact",
            FilmFormula::HamrockDowson => "Hamrock & Dowson 1977, point and elliptical contacts",
        }
    }
}

/// The film at one point of a gear mesh's path of contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathFilm {
    /// Distance from the pitch point along the line of action, m (+ towards the pinion's tip).
    pub s_m: f64,
    pub entrainment_m_per_s: f64,
    pub load_n_per_m: f64,
    pub films: Films,
    pub lambda: Option<f64>,
}

/// The film of a lubricated scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Lubrication {
    pub lubricant: LubricantSpec,
    pub formula: FilmFormula,
    pub conditions: FilmConditions,
    pub films: Films,
    /// Moes' `(M, L)` of the contact.
    pub moes: (f64, f64),
    /// The ellipticity `k` (semi-axis across the entrainment over the one along it) of a point
    /// or elliptical contact.
    pub ellipticity: Option<f64>,
    pub lambda: Option<f64>,
    pub regime: Option<Regime>,
    /// Why the formula's film is doubtful here (empty when it is not).
    pub doubts: Vec<FilmValidity>,
    /// Spur gears with a pinion speed: the film along the path of contact.
    pub path: Vec<PathFilm>,
}

impl Lubrication {
    /// The thinnest minimum film along a gear's path of contact and where, if the scene has a
    /// path.
    pub fn thinnest_on_path(&self) -> Option<&PathFilm> {
        self.path
            .iter()
            .min_by(|a, b| a.films.minimum_m.total_cmp(&b.films.minimum_m))
    }
}

/// The film of `scene`, or `None` without `[lubricant]` (or without the bodies a film needs,
/// which validation refuses).
pub fn films(scene: &Scene) -> Option<Lubrication> {
    let lubricant = scene.lubricant?;
    let dimensional = scene.contact.dimensional?;
    let e_prime = 2.0 * effective_modulus(&dimensional.body1.material, &dimensional.body2.material);
    let conditions = |radius_x_m: f64, entrainment_m_per_s: f64| FilmConditions {
        viscosity_pa_s: lubricant.viscosity_pa_s,
        alpha_per_pa: lubricant.alpha_per_pa,
        reduced_modulus_pa: e_prime,
        entrainment_m_per_s,
        radius_x_m,
    };
    let lambda_of = |films: &Films| {
        lubricant
            .roughness_m
            .map(|sigma| lambda_ratio(films.minimum_m, sigma))
    };
    let (formula, at, films, moes, ellipticity, half_width_m) = match dimensional.hertz {
        Hertz::Line(line) => {
            let at = conditions(line.effective_radius_m, lubricant.entrainment_m_per_s);
            let films = pan_hamrock(&at, line.load_n_per_m);
            (
                FilmFormula::PanHamrock,
                at,
                films,
                at.moes_line(line.load_n_per_m),
                None,
                line.half_width_m,
            )
        }
        Hertz::Point(point) => {
            let at = conditions(point.effective_radius_m, lubricant.entrainment_m_per_s);
            let films = hamrock_dowson(&at, point.load_n, 1.0);
            (
                FilmFormula::HamrockDowson,
                at,
                films,
                at.moes_point(point.load_n),
                Some(1.0),
                point.radius_m,
            )
        }
        Hertz::Elliptical(ellipse) => {
            let radius_x = 0.5 / ellipse.curvature.half_curvature_x_per_m;
            let k = ellipse.semi_axis_y_m / ellipse.semi_axis_x_m;
            let at = conditions(radius_x, lubricant.entrainment_m_per_s);
            let films = hamrock_dowson(&at, ellipse.load_n, k);
            (
                FilmFormula::HamrockDowson,
                at,
                films,
                at.moes_point(ellipse.load_n),
                Some(k),
                ellipse.semi_axis_x_m,
            )
        }
    };
    let doubts = validity(&films, half_width_m, at.radius_x_m, ellipticity);
    let lambda = lambda_of(&films);
    let path = match (
        dimensional.gears,
        lubricant.pinion_rad_per_s,
        dimensional.hertz,
    ) {
        (Some(pair), Some(pinion), Hertz::Line(pitch)) => {
            // The heating's positions: evenly spaced, the pitch point, and both sides of each
            // change in the pairs in mesh.
            crate::study::gear_heating::path_positions(&pair)
                .into_iter()
                .filter_map(|s| {
                    let radii = pair.flank_radii_m(s);
                    let load = pitch.load_n_per_m / pair.pairs_in_contact(s) as f64;
                    let body1 = Body {
                        radius_m: radii[0],
                        ..dimensional.body1
                    };
                    let body2 = Body {
                        radius_m: radii[1],
                        ..dimensional.body2
                    };
                    let line = LineContact::new(&body1, &body2, load).ok()?;
                    let [v1, v2] = pair.flank_speeds_m_per_s(s, pinion);
                    let u = 0.5 * (v1 + v2);
                    let films = pan_hamrock(&conditions(line.effective_radius_m, u), load);
                    Some(PathFilm {
                        s_m: s,
                        entrainment_m_per_s: u,
                        load_n_per_m: load,
                        lambda: lambda_of(&films),
                        films,
                    })
                })
                .collect()
        }
        _ => Vec::new(),
    };
    Some(Lubrication {
        lubricant,
        formula,
        conditions: at,
        films,
        moes,
        ellipticity,
        regime: lambda.map(Regime::of_lambda),
        lambda,
        doubts,
        path,
    })
}
