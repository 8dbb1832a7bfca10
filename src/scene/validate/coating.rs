//! The `[contact.body1.coating]` table: a layer bonded to body 1, and the rigid counter-body a
//! coated scene may take.

#[allow(clippy::wildcard_imports)]
use super::*;
use crate::scene::raw::RawCoating;
use crate::scene::CoatingSpec;

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
        for (key, raw) in [
            ("contact.body1.layers", raw1),
            ("contact.body2.layers", raw2),
        ] {
            if raw.layers.is_some() {
                return Err(self.error(
                    key,
                    "several layers are not computed: the layered response here is that of one layer bonded to a half-space",
                    Some("give one layer as [contact.body1.coating] with thickness and material (or modulus and poisson)"),
                ));
            }
        }
        Ok(())
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
