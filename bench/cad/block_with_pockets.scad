// Differences: a block with a through hole, a blind pocket and a slot.
$fn = 256;
difference() {
    cube([60, 40, 20]);
    translate([15, 20, -1]) cylinder(h = 22, r = 7);
    translate([35, 8, 8]) cube([18, 24, 13]);
    translate([-1, 17, 14]) cube([62, 6, 7]);
}
