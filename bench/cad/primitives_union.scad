// Primitives joined: a box, a cylinder standing on it and a ball on top.
$fn = 48;
union() {
    cube([40, 30, 10], center = true);
    translate([0, 0, 5]) cylinder(h = 20, r = 8);
    translate([0, 0, 28]) sphere(r = 9);
}
