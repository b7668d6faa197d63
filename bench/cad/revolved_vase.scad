// rotate_extrude of a wall profile: a vase, smooth in one direction, facetted in the other.
$fn = 384;
rotate_extrude()
    polygon([[0, 0], [20, 0], [24, 10], [18, 30], [14, 45], [17, 55], [15, 55], [12, 45],
             [16, 30], [22, 10], [18, 2], [0, 2]]);
