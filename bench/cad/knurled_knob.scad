// A knob with a fine knurl: many narrow grooves on a cylinder (the corpus's densest part).
$fn = 360;
difference() {
    union() {
        cylinder(h = 16, r = 20);
        translate([0, 0, 16]) cylinder(h = 6, r1 = 20, r2 = 16);
    }
    for (i = [0 : 59]) rotate(i * 6) translate([20, 0, -1]) cylinder(h = 18, r = 0.9, $fn = 16);
    translate([0, 0, -1]) cylinder(h = 10, r = 4);
}
