// Raised lettering on a plate: many small planar facets and sharp concave corners.
$fn = 24;
union() {
    translate([-5, -5, -3]) cube([70, 22, 3]);
    linear_extrude(height = 1.5) text("VSA 29", size = 12, font = "DejaVu Sans:style=Bold");
}
