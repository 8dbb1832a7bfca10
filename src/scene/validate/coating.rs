//! The `[contact.body1.coating]` table: a layer bonded to body 1, and the rigid counter-body a
//! coated scene may take.

#[allow(clippy::wildcard_imports)]
use super::*;
use crate::scene::raw::{RawCoating, RawLayer};
use crate::scene::{CoatingSpec, Strengths};

/// Coating thicknesses, m.
const THICKNESS_BOUNDS: Bounds = Bounds {
    lo: 1e-9,
    hi: 1.0,
    why: "from a nanometre film to a metre-thick layer",
};

impl Validator<'_> {
    /// The keys a coating may not come with: a coating on body 2, several layers. Checked on
    /// every scene with bodies.
    pub(super) fn coating_placement(
        &self,
        raw1: &RawBody,
        raw2: &RawBody,
    ) -> Result<(), SceneError> {
        if raw2.coating.is_some() {
            return Err(self.error(
                "contact.body2.coating",
                "a coating goes on body 1, the body whose stresses are computed; body 2 is the counter-body",
                Some("make the coated body body 1: move its radius, material and [coating] table to [contact.body1]"),
            ));
        }
        if raw2.layers.is_some() {
            return Err(self.error(
                "contact.body2.layers",
                "layers go on body 1, the body whose stresses are computed; body 2 is the counter-body",
                Some("make the coated body body 1: move its radius, material and [[layers]] tables to [contact.body1]"),
            ));
        }
        if raw1.layers.is_some() && raw1.coating.is_some() {
            return Err(self.error(
                "contact.body1.layers",
                "both [contact.body1.coating] and [[contact.body1.layers]] are given: a body has one stack",
                Some("give a single layer as [contact.body1.coating], or every layer (top first) as [[contact.body1.layers]], not both"),
            ));
        }
        if raw2.yield_strength.is_some() {
            return Err(self.error(
                "contact.body2.yield_strength",
                "the strength check assesses body 1's layers and substrate; body 2's stresses are not computed",
                Some("remove contact.body2.yield_strength"),
            ));
        }
        if raw1.yield_strength.is_some() && raw1.layers.is_none() {
            return Err(self.error(
                "contact.body1.yield_strength",
                "the substrate's yield strength is read with [[contact.body1.layers]] only",
                Some("give the layers as [[contact.body1.layers]] (a single one too), or use contact.yield_strength on an uncoated scene"),
            ));
        }
        Ok(())
    }

    /// The stack `[[contact.body1.layers]]` (top first) of body 1 on a scene of `kind`, with
    /// its strengths and the substrate's `contact.body1.yield_strength`: the top layer as the
    /// coating, the others under it.
    pub(super) fn layers(
        &self,
        kind: ContactKind,
        raw: &[RawLayer],
        substrate_yield: Option<&str>,
        substrate: Material,
        counter: Option<Material>,
    ) -> Result<CoatingSpec, SceneError> {
        match kind {
            ContactKind::Line | ContactKind::Point | ContactKind::Elliptical => {}
            other => {
                return Err(self.error(
                    "contact.body1.layers",
                    format!("several layers are computed on line, point and elliptical contacts, not on kind = \"{}\"", kind_key(other)),
                    Some(match other {
                        ContactKind::Rough => "a rough surface takes a single [contact.body1.coating]; use kind = \"point\" or \"line\" for a stack",
                        _ => "use kind = \"line\", \"point\" or \"elliptical\", or remove the layers",
                    }),
                ))
            }
        }
        if raw.is_empty() || raw.len() > crate::coating::MAX_LAYERS {
            return Err(self.error(
                "contact.body1.layers",
                format!(
                    "{} layers given: a stack takes 1 to {}",
                    raw.len(),
                    crate::coating::MAX_LAYERS
                ),
                Some("give each layer, top first, as a [[contact.body1.layers]] table"),
            ));
        }
        let mut layers = Vec::with_capacity(raw.len());
        let mut strengths = Strengths::default();
        for (i, layer) in raw.iter().enumerate() {
            let key = format!("contact.body1.layers[{}]", i + 1);
            let thickness_key = format!("{key}.thickness");
            let text = layer.thickness.as_deref().ok_or_else(|| {
                self.error(
                    &thickness_key,
                    "missing thickness",
                    Some("add e.g. thickness = \"2 um\""),
                )
            })?;
            let value = units::parse(text, Dimension::Length)
                .map_err(|m| self.error(&thickness_key, m, None))?;
            if value.is_nan() || value <= 0.0 {
                return Err(self.error(
                    &thickness_key,
                    format!(
                        "the thickness must be positive, got `{}`",
                        crate::io::text::cut(text, 40)
                    ),
                    Some("e.g. thickness = \"2 um\"; remove the layer's table to drop it"),
                ));
            }
            let thickness_m = self.within(
                &thickness_key,
                value,
                text,
                Dimension::Length,
                THICKNESS_BOUNDS,
            )?;
            let as_body = RawBody {
                material: layer.material.clone(),
                modulus: layer.modulus.clone(),
                poisson: layer.poisson,
                ..RawBody::default()
            };
            let material = self.elastic(&key, &as_body, "missing elastic modulus")?;
            for (slot, (name, given)) in [
                ("yield_strength", &layer.yield_strength),
                ("tensile_strength", &layer.tensile_strength),
                ("adhesion_strength", &layer.adhesion_strength),
            ]
            .into_iter()
            .enumerate()
            {
                if let Some(text) = given {
                    let pa = self.bounded(
                        &format!("{key}.{name}"),
                        text,
                        Dimension::Pressure,
                        STRESS_BOUNDS,
                    )?;
                    if pa <= 0.0 {
                        return Err(self.error(
                            &format!("{key}.{name}"),
                            "a strength must be positive",
                            Some("e.g. \"1.5 GPa\", or remove the key"),
                        ));
                    }
                    strengths.layers[i][slot] = Some(pa);
                }
            }
            layers.push(crate::coating::Layer {
                material,
                thickness_m,
            });
        }
        if let Some(text) = substrate_yield {
            let pa = self.bounded(
                "contact.body1.yield_strength",
                text,
                Dimension::Pressure,
                STRESS_BOUNDS,
            )?;
            if pa <= 0.0 {
                return Err(self.error(
                    "contact.body1.yield_strength",
                    "a strength must be positive",
                    Some("e.g. \"1.5 GPa\", or remove the key"),
                ));
            }
            strengths.substrate_yield_pa = Some(pa);
        }
        let (counter_per_pa, counter_rigid) = match counter {
            Some(m) => ((1.0 - m.poisson * m.poisson) / m.modulus_pa, false),
            None => (0.0, true),
        };
        let under = crate::coating::Interlayers::of(&layers[1..])
            .ok_or_else(|| self.error("contact.body1.layers", "too many layers", None))?;
        Ok(CoatingSpec {
            thickness_m: layers[0].thickness_m,
            material: layers[0].material,
            substrate,
            counter_per_pa,
            counter_rigid,
            under,
            stacked: true,
            strengths,
        })
    }

    /// The coating of body 1 on a scene of `kind` (line, point, elliptical: gridded gaps;
    /// rough: the surface's grid),
    /// with body 1's own material under it and the counter-body's compliance.
    pub(super) fn coating(
        &self,
        kind: ContactKind,
        raw: &RawCoating,
        substrate: Material,
        counter: Option<Material>,
    ) -> Result<CoatingSpec, SceneError> {
        match kind {
            ContactKind::Line
            | ContactKind::Point
            | ContactKind::Elliptical
            | ContactKind::Rough => {}
            ContactKind::Tractions | ContactKind::Surface => {
                return Err(self.error(
                    "contact.body1.coating",
                    format!("a coating is computed on line, point, elliptical and rough contacts, not on kind = \"{}\"", kind_key(kind)),
                    Some("use kind = \"line\", \"point\", \"elliptical\" or \"rough\", or remove the coating"),
                ))
            }
        }
        let text = raw.thickness.as_deref().ok_or_else(|| {
            self.error(
                "contact.body1.coating.thickness",
                "missing thickness",
                Some("add e.g. thickness = \"2 um\""),
            )
        })?;
        let value = units::parse(text, Dimension::Length)
            .map_err(|m| self.error("contact.body1.coating.thickness", m, None))?;
        if value.is_nan() || value <= 0.0 {
            return Err(self.error(
                "contact.body1.coating.thickness",
                format!(
                    "the thickness must be positive, got `{}`",
                    crate::io::text::cut(text, 40)
                ),
                Some("e.g. thickness = \"2 um\"; remove [contact.body1.coating] for an uncoated body"),
            ));
        }
        let thickness_m = self.within(
            "contact.body1.coating.thickness",
            value,
            text,
            Dimension::Length,
            THICKNESS_BOUNDS,
        )?;
        let as_body = RawBody {
            material: raw.material.clone(),
            modulus: raw.modulus.clone(),
            poisson: raw.poisson,
            ..RawBody::default()
        };
        let material =
            self.elastic("contact.body1.coating", &as_body, "missing elastic modulus")?;
        let (counter_per_pa, counter_rigid) = match counter {
            Some(m) => ((1.0 - m.poisson * m.poisson) / m.modulus_pa, false),
            None => (0.0, true),
        };
        Ok(CoatingSpec {
            thickness_m,
            material,
            substrate,
            counter_per_pa,
            counter_rigid,
            under: crate::coating::Interlayers::NONE,
            stacked: false,
            strengths: Strengths::default(),
        })
    }
}

fn kind_key(kind: ContactKind) -> &'static str {
    match kind {
        ContactKind::Line => "line",
        ContactKind::Point => "point",
        ContactKind::Elliptical => "elliptical",
        ContactKind::Tractions => "tractions",
        ContactKind::Rough => "rough",
        ContactKind::Surface => "surface",
    }
}
