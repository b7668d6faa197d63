// Fillets by hull: a box with rounded edges and corners (the hull of eight balls).
$fn = 96;
hull()
    for (x = [0, 50], y = [0, 30], z = [0, 15]) translate([x, y, z]) sphere(r = 5);
