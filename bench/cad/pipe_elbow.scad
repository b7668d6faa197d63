// A partial revolution: a 90-degree pipe elbow with flat end rings.
$fn = 240;
rotate_extrude(angle = 90)
    translate([30, 0]) difference() { circle(r = 8); circle(r = 6); }
