"""The centre of mass of a polygon, for the benchmark scripts that place a block on its seat."""


def centroid(vertices):
    """The shoelace centre of mass of a counter-clockwise polygon [(x, y), ...]."""
    area = cx = cy = 0.0
    for (x0, y0), (x1, y1) in zip(vertices, vertices[1:] + vertices[:1]):
        cross = x0 * y1 - x1 * y0
        area += cross / 2
        cx += (x0 + x1) * cross
        cy += (y0 + y1) * cross
    return cx / (6 * area), cy / (6 * area)
