// Lettering cut into a block: pockets whose floors and walls are separate planes.
$fn = 24;
difference() {
    translate([-5, -6, -8]) cube([72, 26, 8]);
    translate([0, 0, -1.5]) linear_extrude(height = 2) text("MESH", size = 14, font = "DejaVu Serif");
}
