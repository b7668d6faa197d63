// A ball with three orthogonal cylindrical bores of different radii.
$fn = 72;
difference() {
    sphere(r = 20);
    cylinder(h = 50, r = 6, center = true);
    rotate([90, 0, 0]) cylinder(h = 50, r = 4, center = true);
    rotate([0, 90, 0]) cylinder(h = 50, r = 8, center = true);
}
