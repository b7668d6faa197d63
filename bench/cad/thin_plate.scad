// A thin plate (0.6 thick against 80 wide) with round-ended slots: its two sides nearly touch.
$fn = 96;
difference() {
    cube([80, 50, 0.6]);
    for (i = [0 : 4]) hull() for (y = [13, 37]) translate([13 + i * 14, y, -1]) cylinder(h = 3, r = 3);
    translate([70, 44, -1]) cylinder(h = 3, r = 4);
}
