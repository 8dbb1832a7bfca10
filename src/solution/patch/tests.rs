//! Tests of [`super`].

use super::*;

fn components(s: &Stress) -> [f64; 6] {
    [s.xx, s.yy, s.zz, s.yz, s.xz, s.xy]
}

#[test]
fn centre_of_a_loaded_square_on_the_surface() {
    // Uniform pressure: szz = -p and, at the centre of a square, sxx = syy = -(1 + 2nu)/2
    // (the value of any uniformly loaded region symmetric about the point; Johnson 1985
    // ch. 3 gives it for the circle). qx: sxz = -q, the rest 0 by antisymmetry.
    for nu in [0.0, 0.3, 0.5] {
        let s = uniform_patch(0.0, 0.0, 0.0, Rectangle::centred(0.0, 0.0, 2.0, 2.0), nu);
        let lateral = -(1.0 + 2.0 * nu) / 2.0;
        let expected_p = [lateral, lateral, -1.0, 0.0, 0.0, 0.0];
        let expected_qx = [0.0, 0.0, 0.0, 0.0, -1.0, 0.0];
        let expected_qy = [0.0, 0.0, 0.0, -1.0, 0.0, 0.0];
        for (got, expected) in [
            (components(&s.pressure), expected_p),
            (components(&s.shear_x), expected_qx),
            (components(&s.shear_y), expected_qy),
        ] {
            for i in 0..6 {
                assert!(
                    (got[i] - expected[i]).abs() < 1e-15,
                    "{got:?} vs {expected:?}"
                );
            }
        }
    }
}

#[test]
fn shear_y_is_shear_x_with_x_and_y_exchanged() {
    let rect = Rectangle {
        x1: -0.3,
        x2: 0.8,
        y1: -1.1,
        y2: 0.2,
    };
    let swapped = Rectangle {
        x1: rect.y1,
        x2: rect.y2,
        y1: rect.x1,
        y2: rect.x2,
    };
    for (x, y, z) in [
        (0.1, 0.2, 0.3),
        (-2.0, 0.7, 0.05),
        (1.5, -3.0, 2.0),
        (0.5, 0.5, 0.0),
    ] {
        let qy = uniform_patch(x, y, z, rect, 0.28).shear_y;
        let qx = uniform_patch(y, x, z, swapped, 0.28).shear_x;
        let mapped = [qx.yy, qx.xx, qx.zz, qx.xz, qx.yz, qx.xy];
        let got = components(&qy);
        for i in 0..6 {
            let scale = got[i].abs().max(1.0);
            assert!(
                (got[i] - mapped[i]).abs() < 1e-14 * scale,
                "{got:?} vs {mapped:?}"
            );
        }
    }
}

/// Every component of the three loads' stresses within 1e-14 of `expected`'s (relative, or
/// absolute below 1).
fn assert_patches_close(got: &PatchStresses, expected: &PatchStresses, place: &str) {
    for (g, e) in [
        (got.pressure, expected.pressure),
        (got.shear_x, expected.shear_x),
        (got.shear_y, expected.shear_y),
    ] {
        let (g, e) = (components(&g), components(&e));
        for i in 0..6 {
            assert!(
                (g[i] - e[i]).abs() < 1e-14 * e[i].abs().max(1.0),
                "{place}: {g:?} vs {e:?}"
            );
        }
    }
}

#[test]
fn offsets_of_one_cell_equal_the_rectangle_formula() {
    let (cell, counts) = ([0.3, 0.2], [9, 7]);
    for z in [0.0, 1e-3, 0.1, 2.0] {
        let mut visited = 0;
        uniform_patch_offsets(cell, z, counts, 0.3, |a, b, got| {
            let (x, y) = (a as f64 * cell[0], b as f64 * cell[1]);
            let rect = Rectangle::centred(0.0, 0.0, 0.5 * cell[0], 0.5 * cell[1]);
            let expected = uniform_patch(x, y, z, rect, 0.3);
            assert_patches_close(got, &expected, &format!("({a}, {b}, {z})"));
            visited += 1;
        });
        assert_eq!(visited, 63);
    }
}

#[test]
fn blocks_of_rows_equal_the_whole() {
    let (cell, nx, z) = ([0.3, 0.2], 6, 0.05);
    let mut whole = Vec::new();
    uniform_patch_offsets(cell, z, [nx, 7], 0.3, |a, b, s| whole.push((a, b, *s)));
    let mut blocks = Vec::new();
    for rows in [0..3, 3..4, 4..7] {
        uniform_patch_offset_rows(cell, z, nx, rows, 0.3, |a, b, s| blocks.push((a, b, *s)));
    }
    assert_eq!(whole.len(), blocks.len());
    for ((a, b, s), (a2, b2, s2)) in whole.iter().zip(&blocks) {
        assert_eq!((a, b), (a2, b2));
        assert_patches_close(s, s2, &format!("({a}, {b})"));
    }
}

#[test]
fn mirror_symmetry_of_the_pressure() {
    // x -> -x about the rectangle's centre flips sxz and sxy and keeps the rest.
    let rect = Rectangle::centred(0.0, 0.1, 0.5, 0.25);
    let (a, b) = (
        uniform_patch(0.7, 0.4, 0.2, rect, 0.3).pressure,
        uniform_patch(-0.7, 0.4, 0.2, rect, 0.3).pressure,
    );
    let signs = [1.0, 1.0, 1.0, 1.0, -1.0, -1.0];
    let (a, b) = (components(&a), components(&b));
    for i in 0..6 {
        assert!((a[i] - signs[i] * b[i]).abs() < 1e-15, "{a:?} vs {b:?}");
    }
}
