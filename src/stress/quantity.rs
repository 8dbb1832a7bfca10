//! Scalar quantities that can be drawn or probed, and how each follows from a [`Stress`].

use super::Stress;

/// A scalar measure of the stress tensor.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Quantity {
    Sxx,
    Syy,
    Szz,
    Syz,
    Sxz,
    Sxy,
    /// Largest principal stress.
    S1,
    /// Intermediate principal stress.
    S2,
    /// Smallest (most compressive) principal stress.
    S3,
    VonMises,
    /// Tresca maximum shear `(s1 - s3)/2`.
    MaxShear,
    /// Principal shear in the xz plane (Johnson's `tau_1`).
    Tau1,
    /// Orthogonal shear `tau_xz` (the shear on planes normal and parallel to the surface).
    OrthogonalShear,
    /// Mean normal stress `(sxx + syy + szz)/3`.
    Hydrostatic,
}

/// Whether a quantity takes both signs (drawn with a diverging colour map centred on zero) or is
/// never negative (drawn with a sequential map).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QuantityKind {
    Signed,
    NonNegative,
}

impl Quantity {
    /// Every quantity, in the order used by listings and error messages.
    pub const ALL: [Quantity; 14] = [
        Quantity::Sxx,
        Quantity::Syy,
        Quantity::Szz,
        Quantity::Syz,
        Quantity::Sxz,
        Quantity::Sxy,
        Quantity::S1,
        Quantity::S2,
        Quantity::S3,
        Quantity::VonMises,
        Quantity::MaxShear,
        Quantity::Tau1,
        Quantity::OrthogonalShear,
        Quantity::Hydrostatic,
    ];

    /// The key used in scenes and on the command line.
    pub fn key(self) -> &'static str {
        match self {
            Quantity::Sxx => "sxx",
            Quantity::Syy => "syy",
            Quantity::Szz => "szz",
            Quantity::Syz => "syz",
            Quantity::Sxz => "sxz",
            Quantity::Sxy => "sxy",
            Quantity::S1 => "s1",
            Quantity::S2 => "s2",
            Quantity::S3 => "s3",
            Quantity::VonMises => "von_mises",
            Quantity::MaxShear => "max_shear",
            Quantity::Tau1 => "tau1",
            Quantity::OrthogonalShear => "orthogonal_shear",
            Quantity::Hydrostatic => "hydrostatic",
        }
    }

    /// Parses a scene or command-line key (see [`Quantity::key`]).
    pub fn from_key(key: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|q| q.key() == key)
    }

    /// The symbol drawn on figures (Unicode; DejaVu Sans has every glyph).
    pub fn symbol(self) -> &'static str {
        match self {
            Quantity::Sxx => "σxx",
            Quantity::Syy => "σyy",
            Quantity::Szz => "σzz",
            Quantity::Syz => "τyz",
            Quantity::Sxz => "τxz",
            Quantity::Sxy => "τxy",
            Quantity::S1 => "σ1",
            Quantity::S2 => "σ2",
            Quantity::S3 => "σ3",
            Quantity::VonMises => "σvM",
            Quantity::MaxShear => "τmax",
            Quantity::Tau1 => "τ1",
            Quantity::OrthogonalShear => "τxz",
            Quantity::Hydrostatic => "σh",
        }
    }

    /// A short description for titles and legends.
    pub fn description(self) -> &'static str {
        match self {
            Quantity::Sxx => "normal stress σxx",
            Quantity::Syy => "normal stress σyy",
            Quantity::Szz => "normal stress σzz",
            Quantity::Syz => "shear stress τyz",
            Quantity::Sxz => "shear stress τxz",
            Quantity::Sxy => "shear stress τxy",
            Quantity::S1 => "largest principal stress σ1",
            Quantity::S2 => "intermediate principal stress σ2",
            Quantity::S3 => "smallest principal stress σ3",
            Quantity::VonMises => "von Mises stress σvM",
            Quantity::MaxShear => "maximum shear stress τmax = (σ1 − σ3)/2",
            Quantity::Tau1 => "principal shear stress τ1 (xz plane)",
            Quantity::OrthogonalShear => "orthogonal shear stress τxz",
            Quantity::Hydrostatic => "hydrostatic stress σh",
        }
    }

    pub fn kind(self) -> QuantityKind {
        match self {
            Quantity::VonMises | Quantity::MaxShear | Quantity::Tau1 => QuantityKind::NonNegative,
            _ => QuantityKind::Signed,
        }
    }

    /// Evaluates the quantity for one stress state.
    #[inline]
    pub fn of(self, stress: &Stress) -> f64 {
        match self {
            Quantity::Sxx => stress.xx,
            Quantity::Syy => stress.yy,
            Quantity::Szz => stress.zz,
            Quantity::Syz => stress.yz,
            Quantity::Sxz | Quantity::OrthogonalShear => stress.xz,
            Quantity::Sxy => stress.xy,
            Quantity::S1 => stress.principal()[0],
            Quantity::S2 => stress.principal()[1],
            Quantity::S3 => stress.principal()[2],
            Quantity::VonMises => stress.von_mises(),
            Quantity::MaxShear => stress.max_shear(),
            Quantity::Tau1 => stress.principal_shear_xz(),
            Quantity::Hydrostatic => stress.hydrostatic(),
        }
    }
}

impl std::fmt::Display for Quantity {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.key())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_round_trip() {
        for q in Quantity::ALL {
            assert_eq!(Quantity::from_key(q.key()), Some(q));
        }
        assert_eq!(Quantity::from_key("vonmises"), None);
    }
}
