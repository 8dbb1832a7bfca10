//! A rough or surface scene beyond its `[contact]`: the tables it may and may not have, the
//! solver settings of `[numerical]`, the limits of what presses the contact against its
//! surface, the depth of its section, and its sweep or wear.

#[allow(clippy::wildcard_imports)]
use super::*;
use crate::contact::rough::Control;
use crate::surface::HeightMap;

impl Validator<'_> {
    /// A rough or surface scene: its tables beyond `[contact]`.
    pub(super) fn rough_scene(
        &self,
        raw: RawScene,
        name: &str,
        mut contact: Contact,
    ) -> Result<Scene, SceneError> {
        let periodic = contact.rough.is_some_and(|r| r.periodic);
        let surface = self.surface_spec(&raw, contact.kind, periodic)?;
        if let Some(coating) = &contact.coating {
            self.coated_rough(&raw, coating, &surface.heights)?;
        }
        if let Some(i) = raw.panels.iter().position(|p| p.section.is_some()) {
            return Err(self.error(
                &format!("panel[{i}].section"),
                "a rough or surface scene chooses its own sections: the xz section through the report's maximum and the plane at its depth (or, for a surface, none)",
                Some("remove the [[panel]] table; to cut a smooth contact in several planes use kind = \"point\" or \"elliptical\""),
            ));
        }
        for (key, given) in [
            ("panel", !raw.panels.is_empty()),
            ("tractions", raw.tractions.is_some()),
            (
                "sweep",
                raw.sweep.is_some() && contact.kind == ContactKind::Surface,
            ),
            ("volume", raw.volume.is_some()),
            ("figure.section", raw.figure.section.is_some()),
            ("figure.at", raw.figure.at.is_some()),
            ("figure.x", raw.figure.x.is_some()),
            ("figure.y", raw.figure.y.is_some()),
            (
                "figure.z",
                raw.figure.z.is_some() && contact.kind == ContactKind::Surface,
            ),
            ("figure.resolution", raw.figure.resolution.is_some()),
        ] {
            if given {
                return Err(self.error(
                    key,
                    "a rough or surface scene draws its own set of panels (topography, pressure, sections through the peak; or the surface's statistics)",
                    Some("remove it; docs/rough-contact.md describes the sheet's sections"),
                ));
            }
        }
        if let (Some(numerical), Some(rough)) = (&raw.numerical, contact.rough.as_mut()) {
            if numerical.cells.is_some() || numerical.extent.is_some() {
                let key = if numerical.cells.is_some() {
                    "numerical.cells"
                } else {
                    "numerical.extent"
                };
                return Err(self.error(
                    key,
                    "the grid of a rough contact is the surface's",
                    Some("remove it; numerical takes tolerance and max_iterations here"),
                ));
            }
            if let Some(t) = numerical.tolerance {
                if !(t > 0.0 && t < crate::scene::MAX_ROUGH_TOLERANCE) {
                    return Err(self.error(
                        "numerical.tolerance",
                        format!(
                            "must lie in (0, {}), got {}",
                            crate::io::text::number(crate::scene::MAX_ROUGH_TOLERANCE),
                            crate::io::text::number(t)
                        ),
                        Some("the default is 1e-8"),
                    ));
                }
                rough.tolerance = t;
            }
            if let Some(n) = numerical.max_iterations {
                if !(10..=1_000_000).contains(&n) {
                    return Err(self.error(
                        "numerical.max_iterations",
                        format!("must lie in 10..=1000000, got {n}"),
                        None,
                    ));
                }
                rough.max_iterations = n as usize;
            }
        }
        let hardness_key = if raw.contact.hardness.is_some() {
            "contact.hardness"
        } else {
            "contact.yield_strength"
        };
        if let Some(rough) = &contact.rough {
            let key = match rough.control {
                Some(Control::Load { .. }) => "contact.load",
                Some(Control::MeanPressure { .. }) => "contact.mean_pressure",
                _ => "contact.approach",
            };
            self.rough_control(rough, key, &surface.heights, hardness_key)?;
        }
        let figure = self.figure(&raw.figure, &contact, &[])?;
        if figure.depth_given {
            self.rough_section_depth(&figure, &surface.heights)?;
        }
        let thermal = self.thermal(&raw, &contact)?;
        let [ny, nx] = surface.heights.shape();
        let mut scene = Scene {
            name: name.into(),
            title: raw.title.clone(),
            contact,
            figure,
            panels: Vec::new(),
            numerical: Numerical {
                cells: nx.max(ny),
                extent_over_a: 1.0,
            },
            tractions: None,
            sweep: None,
            volume: None,
            load_centre_over_a: 0.0,
            thermal,
            surface: Some(surface),
            wear: None,
            plasticity: None,
            lubricant: None,
        };
        scene.wear = self.wear(&raw, &scene)?;
        if let Some(sweep) = &raw.sweep {
            if scene.wear.is_some() {
                return Err(self.error(
                    "sweep",
                    "a wear scene steps along the sliding distance: it takes no other sweep",
                    Some("remove [sweep]; `stressfield record` records the wear steps against the sliding distance"),
                ));
            }
            let sweep = self.sweep(sweep, &scene)?;
            // Each load of a rough sweep is held to the limits of the scene's own load.
            if let (Some(rough), Some(surface)) = (&scene.contact.rough, &scene.surface) {
                for (k, &newtons) in sweep.values.iter().enumerate() {
                    let stepped = RoughSpec {
                        control: Some(Control::Load { newtons }),
                        ..*rough
                    };
                    self.rough_control(
                        &stepped,
                        &sweep.value_key(k),
                        &surface.heights,
                        hardness_key,
                    )?;
                }
            }
            scene.sweep = Some(sweep);
        }
        if let Some(table) = &raw.plasticity {
            scene.plasticity = Some(self.plasticity(table, &raw, &scene)?);
        }
        Ok(scene)
    }

    /// What presses a rough contact, against its surface: a mean pressure over the map below
    /// the combined modulus E* (beyond it the strains would be of order one, far outside
    /// elasticity, and the surfaces flattened), an approach below the surface's peak-to-valley
    /// height (beyond it the surfaces overlap everywhere). With a hardness `H` (the pressure
    /// cap) the load must also stay below `H` times the nominal area: the most the fully
    /// plastic surface carries. `hardness_key` is the key the hardness came from.
    ///
    /// Periodic and without a hardness, an approach must also stay below the highest point's
    /// height above the mean plane (Sp): a periodic surface's mean displacement is zero, so the
    /// mean gap is that height less the approach, and at it the gap closes everywhere (beyond
    /// it there is no elastic solution).
    ///
    /// `key` names the load, mean pressure or approach (`contact.load`, or a sweep's
    /// `sweep.values[i]` for each of its loads).
    /// What a coated rough scene may not have, and the grid its coating needs: cells of at
    /// most half the coating's thickness ([`crate::coating::kernel::MIN_THICKNESS_CELLS`]).
    fn coated_rough(
        &self,
        raw: &RawScene,
        coating: &crate::scene::CoatingSpec,
        heights: &HeightMap,
    ) -> Result<(), SceneError> {
        for (key, given, what) in [
            (
                "thermal",
                raw.thermal.is_some(),
                "frictional heating of a coated body",
            ),
            ("wear", raw.wear.is_some(), "wear of a coated surface"),
            (
                "series",
                !raw.series.is_empty(),
                "a series of a coated surface",
            ),
            (
                "sweep",
                raw.sweep.is_some(),
                "a sweep of a coated rough contact",
            ),
        ] {
            if given {
                return Err(self.error(
                    key,
                    format!("{what} is not computed"),
                    Some("remove the table; `contact` reports the coated rough contact and its stresses, `render` draws its sheet"),
                ));
            }
        }
        let [dx, dy] = heights.spacing_m();
        let cell = dx.max(dy);
        let largest = crate::contact::coated::largest_cell_m(coating.thickness_m);
        if cell > largest * (1.0 + 1e-12) {
            let key = if raw.surface.as_ref().is_some_and(|s| s.generate.is_some()) {
                "surface.generate.spacing"
            } else {
                "surface.spacing"
            };
            return Err(self.error(
                "contact.body1.coating.thickness",
                format!(
                    "the coating ({} µm) is thinner than two of the surface's cells ({} µm): its layered kernels and the stress samples inside it need cells of at most {} µm",
                    crate::io::text::approx(coating.thickness_m * 1e6),
                    crate::io::text::approx(cell * 1e6),
                    crate::io::text::approx(largest * 1e6)
                ),
                Some(&format!("give a coating at least {} µm thick, or a map sampled at most {} µm apart ({key})", crate::io::text::approx(2.0 * cell * 1e6), crate::io::text::approx(largest * 1e6))),
            ));
        }
        let [ny, nx] = heights.shape();
        if nx.max(ny) > crate::study::coated::MAX_CELLS {
            return Err(self.error(
                "contact.body1.coating",
                format!(
                    "a coated rough contact takes maps of at most {} samples per side (its layered kernel is built on a grid four times as wide), got {nx} x {ny}",
                    crate::study::coated::MAX_CELLS
                ),
                Some("crop or resample the map, or remove the coating"),
            ));
        }
        Ok(())
    }

    fn rough_control(
        &self,
        rough: &RoughSpec,
        key: &str,
        heights: &HeightMap,
        hardness_key: &str,
    ) -> Result<(), SceneError> {
        let [width_m, length_m] = heights.size_m();
        let area_m2 = width_m * length_m;
        let aspect = width_m.max(length_m) / width_m.min(length_m);
        if rough.periodic && aspect > crate::operator::elastic::MAX_PERIODIC_ASPECT {
            return Err(self.error(
                "contact.periodic",
                format!(
                    "the map is {} times longer than wide ({} x {} m): a periodic contact's kernel sums the images out to 1.5 times the longer side, so its time grows with the square of the longer side; at most {} here",
                    crate::io::text::approx(aspect),
                    crate::io::text::approx(width_m),
                    crate::io::text::approx(length_m),
                    crate::operator::elastic::MAX_PERIODIC_ASPECT
                ),
                Some("solve it as an isolated contact (periodic = false), or use a map closer to square"),
            ));
        }
        let mean_pa = match rough.control {
            Some(Control::Load { newtons }) => Some((key, newtons / area_m2)),
            Some(Control::MeanPressure { pa }) => Some((key, pa)),
            _ => None,
        };
        if let (Some((key, mean_pa)), Some(hardness_pa)) = (mean_pa, rough.hardness_pa) {
            if mean_pa >= hardness_pa {
                return Err(self.error(
                    key,
                    format!(
                        "a mean pressure of {} Pa over the map's {} m² is more than the fully plastic surface carries: the hardness ({hardness_key}) caps the pressure at {} Pa, so at most {} N",
                        crate::io::text::approx(mean_pa),
                        crate::io::text::approx(area_m2),
                        crate::io::text::approx(hardness_pa),
                        crate::io::text::approx(hardness_pa * area_m2)
                    ),
                    Some(&format!("lower {key}, give a larger map, or check {hardness_key} (a pressure capped at H carries at most H times the nominal area)")),
                ));
            }
        }
        match (rough.control, rough.e_star_pa) {
            (Some(Control::Load { newtons }), Some(e_star)) if newtons / area_m2 > e_star => {
                Err(self.error(
                    key,
                    format!(
                        "{} N over the map's {} m² is a mean pressure of {} Pa, more than the combined modulus E* = {} Pa",
                        crate::io::text::approx(newtons),
                        crate::io::text::approx(area_m2),
                        crate::io::text::approx(newtons / area_m2),
                        crate::io::text::approx(e_star)
                    ),
                    Some("rough contact is elastic (up to a hardness cap): give a load whose mean pressure over the map is a small fraction of E*, or a larger map"),
                ))
            }
            (Some(Control::MeanPressure { pa }), Some(e_star)) if pa > e_star => Err(self.error(
                key,
                format!(
                    "{} Pa is more than the combined modulus E* = {} Pa",
                    crate::io::text::approx(pa),
                    crate::io::text::approx(e_star)
                ),
                Some("rough contact is elastic (up to a hardness cap): give a small fraction of E*"),
            )),
            (Some(Control::Approach { m }), _) => {
                let map = heights.heights_m();
                let (low, high) = map
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &h| {
                        (lo.min(h), hi.max(h))
                    });
                let mean = map.sum() / map.len() as f64;
                if m > high - low {
                    Err(self.error(
                        key,
                        format!(
                            "{} m is more than the surface's peak-to-valley height {} m: the surfaces would overlap everywhere",
                            crate::io::text::approx(m),
                            crate::io::text::approx(high - low)
                        ),
                        Some("the approach is counted from first contact: give a fraction of the peak-to-valley height"),
                    ))
                } else if rough.periodic
                    && rough.hardness_pa.is_none()
                    && m >= (high - mean) * (1.0 - crate::contact::rough::FULL_CONTACT_MARGIN)
                {
                    Err(self.error(
                        key,
                        format!(
                            "{} m closes the gap everywhere (full contact): a periodic surface's mean displacement is zero, so its mean gap is the highest point's height above the mean plane, {} m, less the approach",
                            crate::io::text::approx(m),
                            crate::io::text::approx(high - mean)
                        ),
                        Some("give an approach below that height, or press it by a load (contact.load or contact.mean_pressure), which never closes the gap completely"),
                    ))
                } else {
                    Ok(())
                }
            }
            _ => Ok(()),
        }
    }

    /// A rough scene's `[figure] z`: the depth range of its xz section, which is drawn over
    /// at least [`ROUGH_SECTION_MIN_CELLS`] of the map's cells along x (the whole row when the
    /// range is deep) at equal scale and at least
    /// [`ROUGH_SECTION_MIN_DEPTH_OVER_WIDTH`] as deep as wide: the range spans at least that
    /// fraction of those cells, and at most [`ROUGH_SECTION_MAX_DEPTH_OVER_WIDTH`] times the
    /// map's width.
    fn rough_section_depth(
        &self,
        figure: &FigureSpec,
        heights: &crate::surface::HeightMap,
    ) -> Result<(), SceneError> {
        let per_um = figure.length_unit.metres(1e-6) / 1e-6;
        let (z0, z1) = figure.z;
        let span_um = (z1 - z0) * per_um;
        let [_, nx] = heights.shape();
        let cell_um = heights.spacing_m()[0] * 1e6;
        let width_um = nx as f64 * cell_um;
        let suffix = unit_after(figure.length_unit);
        let shallowest_um =
            ROUGH_SECTION_MIN_DEPTH_OVER_WIDTH * ROUGH_SECTION_MIN_CELLS.min(nx) as f64 * cell_um;
        let in_unit = |um: f64| crate::io::text::approx(um / per_um);
        if span_um < shallowest_um * (1.0 - 1e-9) {
            return Err(self.error(
                "figure.z",
                format!(
                    "the depth range [{}, {}] spans {}{suffix}, less than a quarter of the {} cells ({}{suffix}) a section shows at least",
                    crate::io::text::number(z0),
                    crate::io::text::number(z1),
                    in_unit(span_um),
                    ROUGH_SECTION_MIN_CELLS.min(nx),
                    in_unit(ROUGH_SECTION_MIN_CELLS.min(nx) as f64 * cell_um),
                ),
                Some(&format!(
                    "give a range at least {}{suffix} deep, or a surface with finer samples",
                    in_unit(shallowest_um)
                )),
            ));
        }
        if span_um > ROUGH_SECTION_MAX_DEPTH_OVER_WIDTH * width_um {
            return Err(self.error(
                "figure.z",
                format!(
                    "the depth range [{}, {}] is more than {} times as deep as the map is wide ({}{suffix}): the section would be a tower",
                    crate::io::text::number(z0),
                    crate::io::text::number(z1),
                    crate::io::text::compact(ROUGH_SECTION_MAX_DEPTH_OVER_WIDTH),
                    in_unit(width_um),
                ),
                Some(&format!(
                    "give a range at most {}{suffix} deep",
                    in_unit(ROUGH_SECTION_MAX_DEPTH_OVER_WIDTH * width_um)
                )),
            ));
        }
        Ok(())
    }
}
