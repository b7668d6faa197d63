// A hexagon nut: a hexagonal prism with a bore, its corners chamfered by a double cone.
$fn = 64;
difference() {
    intersection() {
        cylinder(h = 12, r = 15, $fn = 6);
        union() {
            cylinder(h = 6, r1 = 12, r2 = 18);
            translate([0, 0, 6]) cylinder(h = 6, r1 = 18, r2 = 12);
        }
    }
    translate([0, 0, -1]) cylinder(h = 14, r = 7);
}
