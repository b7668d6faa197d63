// Fillets by Minkowski sum: a plate with a cut-out, its vertical edges rounded by a cylinder.
$fn = 96;
minkowski() {
    difference() {
        cube([60, 40, 4]);
        translate([20, 12, -1]) cube([20, 16, 6]);
    }
    cylinder(r = 3, h = 1);
}
