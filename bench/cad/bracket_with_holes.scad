// An L bracket with a gusset, two slotted holes and two round holes.
$fn = 48;
difference() {
    union() {
        cube([60, 30, 5]);
        cube([5, 30, 40]);
        translate([5, 17, 5]) rotate([90, 0, 0]) linear_extrude(height = 4)
            polygon([[0, 0], [30, 0], [0, 30]]);
    }
    for (x = [25, 48]) hull() for (dy = [-4, 4]) translate([x, 15 + dy, -1]) cylinder(h = 7, r = 3);
    for (y = [8, 22]) translate([-1, y, 28]) rotate([0, 90, 0]) cylinder(h = 7, r = 3.5);
}
