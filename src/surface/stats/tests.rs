//! Tests of [`super`].

use super::*;

fn map(ny: usize, nx: usize, dx: f64, f: impl Fn(f64, f64) -> f64) -> HeightMap {
    HeightMap::new(
        Array2::from_shape_fn((ny, nx), |(j, i)| f(i as f64 * dx, j as f64 * dx)),
        [dx, dx],
    )
    .expect("map")
}

#[test]
fn a_sampled_sinusoid_has_the_closed_form_height_parameters() {
    // A cos(2π(x - xc)/λ) about the map's centre, λ dividing the map: Sq = A/√2,
    // Sa = 2A/π, Ssk = 0, Sku = 1.5 (the sample means of cos^k over whole periods are
    // exact); being even about the centre it has no least-squares plane to remove.
    let (a, lambda, n) = (1e-6, 32.0, 128);
    let centre = 0.5 * (n - 1) as f64;
    let sine = map(16, n, 1.0, |x, _| {
        a * (2.0 * PI * (x - centre) / lambda).cos()
    });
    let c = characterise(
        &sine,
        &Options {
            window: false,
            ..Options::default()
        },
    )
    .expect("ok");
    let h = c.height;
    assert!(
        (h.sq / (a / 2f64.sqrt()) - 1.0).abs() < 1e-12,
        "Sq {}",
        h.sq
    );
    // Sa of samples of a sine at 32 points per period: 2A/π to the sampling (1e-3).
    assert!((h.sa / (2.0 * a / PI) - 1.0).abs() < 2e-3, "Sa {}", h.sa);
    assert!(h.ssk.abs() < 1e-12, "Ssk {}", h.ssk);
    assert!((h.sku - 1.5).abs() < 1e-12, "Sku {}", h.sku);
    assert!((h.sp - a).abs() < 0.01 * a && (h.sv - a).abs() < 0.01 * a);
    // Profile values equal the areal ones for a surface uniform in y.
    assert!((c.profile.rq / h.sq - 1.0).abs() < 1e-3);
    // Sdq = A 2π/λ /√2 to the finite difference, (2 sin(π/λ)) A /√2, over whole periods;
    // the map's 127 cells miss one difference of the 128 of four periods (< 1 %).
    let sdq = 2.0 * (PI / lambda).sin() * a / 2f64.sqrt();
    assert!((c.sdq / sdq - 1.0).abs() < 0.01, "Sdq {} vs {sdq}", c.sdq);
    // Sal: the ACF cos(2πτ/λ) falls to 0.2 at λ acos(0.2)/(2π) along x, never along y.
    let sal = lambda * 0.2f64.acos() / (2.0 * PI);
    let measured = c.spatial.sal_m.expect("decays along x");
    assert!((measured - sal).abs() < 0.05, "Sal {measured} vs {sal}");
    assert!(c.spatial.str_bounded);
}

#[test]
fn a_tilted_plane_is_all_zero_after_levelling() {
    let plane = map(20, 30, 1e-6, |x, y| 3e-6 + 0.01 * x - 0.02 * y);
    let (z, coefficients) = level(&plane, FormRemoval::Plane);
    assert!(
        z.iter().all(|v| v.abs() < 1e-18),
        "{}",
        z.iter().fold(0.0f64, |m, v| m.max(v.abs()))
    );
    assert!((coefficients[1] - 0.01).abs() < 1e-12 && (coefficients[2] + 0.02).abs() < 1e-12);
    assert!((coefficients[0] - 3e-6).abs() < 1e-18);
    let h = height_parameters(&z);
    for value in [h.sa, h.sq, h.sp, h.sv, h.sz] {
        assert!(value < 1e-18);
    }
    assert_eq!(
        characterise(&plane, &Options::default()),
        Err(StatsError::Flat)
    );
}

#[test]
fn a_sampled_sphere_has_its_radius_as_summit_radius() {
    // One summit at the top of a sphere of radius R = 5 mm sampled every 1 um; with a
    // quadratic form removed nothing remains, so summits are measured on the raw cap.
    let radius = 5e-3;
    let cap = map(41, 41, 1e-6, |x, y| {
        let r2 = (x - 20e-6).powi(2) + (y - 20e-6).powi(2);
        (radius * radius - r2).sqrt() - radius
    });
    let s = summits(cap.heights_m(), cap.spacing_m());
    assert_eq!(s.count, 1);
    assert!((s.radius_m / radius - 1.0).abs() < 1e-6, "{}", s.radius_m);
    let (levelled, _) = level(&cap, FormRemoval::Plane);
    let asperity = highest_asperity(&levelled, cap.spacing_m());
    assert_eq!(asperity.at, [20, 20]);
    let rx = asperity.radius_x_m.expect("convex");
    assert!((rx / radius - 1.0).abs() < 1e-6, "{rx}");
}

#[test]
fn summit_density_of_an_egg_box() {
    // cos(2πx/λ) cos(2πy/λ): maxima where both are 1 or both -1, two per λ² cell.
    let lambda = 16.0;
    let egg = map(128, 128, 1.0, |x, y| {
        (2.0 * PI * x / lambda).cos() * (2.0 * PI * y / lambda).cos()
    });
    let s = summits(egg.heights_m(), egg.spacing_m());
    let expected = 2.0 / (lambda * lambda);
    assert!(
        (s.density_per_m2 / expected - 1.0).abs() < 0.1,
        "{} vs {expected}",
        s.density_per_m2
    );
}

#[test]
fn psd_normalisation_keeps_the_variance() {
    // White-ish noise from a small LCG: Σ C Δq²/(2π)² = Sq², Σ C1 Δq/2π = Rq² (no window).
    let mut state = 12345u64;
    let mut noise = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 11) as f64 / (1u64 << 53) as f64) - 0.5
    };
    let (n, dx) = (64, 2e-6);
    let heights = Array2::from_shape_simple_fn((n, n), || 1e-6 * noise());
    let m = HeightMap::new(heights, [dx, dx]).expect("map");
    let (z, _) = level(&m, FormRemoval::Plane);
    let plan = RealFft2::new([n, n]);
    let mut work = plan.work();
    let mut spectrum = plan.new_spectrum();
    plan.forward(z.view(), &mut spectrum, &mut work)
        .expect("fft");
    let l = n as f64 * dx;
    let factor = dx * dx / (n * n) as f64;
    let mut total = 0.0;
    for ((kx, _), v) in spectrum.indexed_iter() {
        let weight = if kx == 0 || kx == n / 2 { 1.0 } else { 2.0 };
        total += weight * factor * v.norm_sqr();
    }
    let dq = 2.0 * PI / l;
    let variance = z.iter().map(|v| v * v).sum::<f64>() / (n * n) as f64;
    assert!((total * dq * dq / (4.0 * PI * PI) / variance - 1.0).abs() < 1e-12);
    let c = characterise(
        &m,
        &Options {
            window: false,
            ..Options::default()
        },
    )
    .expect("ok");
    // The 1-D PSD: two-sided sum over ±qx (and qx = 0) equals the mean row variance.
    let mut one_d = 0.0;
    for (k, (_, value)) in c.spectra.profile.iter().enumerate() {
        one_d += if k + 1 == n / 2 { 1.0 } else { 2.0 } * value;
    }
    let row_dc: f64 = z
        .rows()
        .into_iter()
        .map(|r| (r.sum() / n as f64).powi(2))
        .sum::<f64>()
        / n as f64;
    let expected = variance - row_dc;
    assert!(
        (one_d * dq / (2.0 * PI) / expected - 1.0).abs() < 1e-10,
        "{one_d}"
    );
}

/// Issue 24, class 3: the memory of a characterisation is estimated from the grid before
/// anything is allocated. Under the 6 GB a machine of 8 GB allows (3/4), 16384² (about
/// 12 GiB) is refused with the size, the estimate, the limit and the fix; 8192² (3 GiB) runs.
#[test]
fn a_map_too_large_for_the_memory_is_refused_before_characterising() {
    let limit = 6_000_000_000;
    let error = check_memory([16384, 16384], limit)
        .expect_err("too large")
        .to_string();
    for fragment in [
        "16384 x 16384 samples",
        "about 12 GiB",
        "5.6 GiB allowed",
        "crop or resample",
    ] {
        assert!(error.contains(fragment), "{fragment}: {error}");
    }
    assert!(check_memory([8192, 8192], limit).is_ok());
    // Far beyond any machine, without overflow.
    assert!(check_memory([usize::MAX, usize::MAX], limit).is_err());
}

#[test]
fn the_highest_asperity_is_a_summit_off_the_edges() {
    // A bump at the map's centre and a higher one centred on the second row (the worn map's
    // highest sample lay on row 1, its circle cut by the edge): the asperity is the centre's,
    // a summit whose neighbours and drawn ring lie inside the map.
    let bump = |x: f64, y: f64, cx: f64, cy: f64, h: f64| {
        h * (-((x - cx).powi(2) + (y - cy).powi(2)) / 8.0).exp()
    };
    // Samples 1 µm apart, heights of 1 and 2 µm.
    let m = map(32, 32, 1e-6, |x, y| {
        let (x, y) = (x * 1e6, y * 1e6);
        1e-6 * (bump(x, y, 16.0, 16.0, 1.0) + bump(x, y, 10.0, 1.0, 2.0))
    });
    let asperity = highest_asperity(m.heights_m(), m.spacing_m());
    assert_eq!(asperity.at, [16, 16]);
    assert!(
        (asperity.height_m - 1e-6).abs() < 1e-9,
        "{}",
        asperity.height_m
    );
}
