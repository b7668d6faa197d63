// Linear extrusion with a twist: a star whose sides are curved (ruled) surfaces.
linear_extrude(height = 40, twist = 90, slices = 120)
    polygon([for (i = [0 : 9]) let(r = i % 2 == 0 ? 15 : 7, a = i * 36) [r * cos(a), r * sin(a)]]);
