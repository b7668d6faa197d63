// A revolved flange with a raised neck and six bolt holes around it.
$fn = 96;
difference() {
    rotate_extrude() polygon([[10, 0], [40, 0], [40, 8], [18, 8], [15, 25], [10, 25]]);
    for (i = [0 : 5]) rotate(i * 60) translate([30, 0, -1]) cylinder(h = 10, r = 3, $fn = 32);
}
