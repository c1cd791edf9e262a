"""trifiles.py — what the checkers of Triangle's files share (check_regions.py,
check_reference.py, check_voronoi.py)."""


def tokens(path):
    """The file's lines as lists of fields, '#' comments and blank lines dropped."""
    out = []
    with open(path) as f:
        for line in f:
            fields = line.split('#', 1)[0].split()
            if fields:
                out.append(fields)
    return out
