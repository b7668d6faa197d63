// A spur-gear-like part: 24 trapezoid teeth, a hub, a keyed bore and lightening holes.
$fn = 64;
teeth = 24;
difference() {
    union() {
        linear_extrude(height = 8) union() {
            circle(r = 26);
            for (i = [0 : teeth - 1]) rotate(i * 360 / teeth)
                polygon([[25, -3], [31, -1.6], [31, 1.6], [25, 3]]);
        }
        cylinder(h = 14, r = 10);
    }
    translate([0, 0, -1]) cylinder(h = 16, r = 5);
    translate([4, -1.5, -1]) cube([3, 3, 16]);
    for (i = [0 : 5]) rotate(i * 60) translate([17, 0, -1]) cylinder(h = 10, r = 4);
}
