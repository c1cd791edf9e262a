#!/usr/bin/env python3
"""svg_check.py FILE...: each SVG that test_svg wrote is well-formed XML with an <svg>
root and a viewBox, and every path's data uses only the writer's commands (M, l, h, a)
with integer numbers (no nan or inf)."""
import re
import sys
import xml.dom.minidom

PATH_DATA = re.compile(r'^(?:M-?\d+ -?\d+(?:l-?\d+ -?\d+|h0|(?:a\d+ \d+ 0 1 0 -?\d+ 0){2}))*$')

def check(name):
    doc = xml.dom.minidom.parse(name)
    root = doc.documentElement
    assert root.tagName == 'svg', name + ': root is not <svg>'
    assert len(root.getAttribute('viewBox').split()) == 4, name + ': no viewBox'
    paths = doc.getElementsByTagName('path')
    for p in paths:
        assert PATH_DATA.match(p.getAttribute('d')), name + ': odd path data ' + p.getAttribute('d')[:80]
    return len(paths)

if __name__ == '__main__':
    if len(sys.argv) < 2:
        sys.exit('usage: svg_check.py FILE...')
    for name in sys.argv[1:]:
        print('%s: well-formed, %d path elements' % (name, check(name)))
