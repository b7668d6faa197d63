// Linear extrusion of a T-slot-like profile with rounded corners: long planar sides and
// narrow cylindrical strips along them.
linear_extrude(height = 80)
    offset(r = 1, $fn = 48) offset(delta = -1)
        difference() {
            square([20, 20], center = true);
            for (a = [0 : 90 : 270]) rotate(a) translate([8, 0]) square([6, 4], center = true);
            circle(r = 2.5, $fn = 64);
        }
