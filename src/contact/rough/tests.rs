//! Tests of [`super`].

use super::*;

#[test]
fn spots_are_4_connected_and_wrap_when_periodic() {
    let mut p = Array2::zeros((5, 6));
    for at in [[0, 0], [0, 1], [1, 1], [3, 3], [4, 4], [2, 5]] {
        p[at] = 1.0;
    }
    // {00, 01, 11}, {33}, {44}, {25}: four; periodic: 25 touches 20? no (0 at [2,0]);
    // 44 wraps to 04? no; 00 wraps to 05 and 40: not loaded. Still four.
    assert_eq!(count_spots(&p, false), 4);
    assert_eq!(count_spots(&p, true), 4);
    p[[2, 0]] = 1.0;
    assert_eq!(count_spots(&p, false), 5);
    assert_eq!(
        count_spots(&p, true),
        4,
        "[2, 0] joins [2, 5] across the edge"
    );
}
