"""gen_check.py -- the command line the generators of lib/gen share:

    python3 lib/gen/GENERATOR.py [--check] OUTPUT

writes OUTPUT, or with --check compares it with what the generator writes and exits 1
when it differs (CI runs that)."""
import os
import sys


def main(argv, generate):
    name = os.path.basename(argv[0])
    check = "--check" in argv
    paths = [a for a in argv[1:] if a != "--check"]
    if len(paths) != 1:
        sys.stderr.write("usage: %s [--check] OUTPUT\n" % name)
        return 2
    text = generate()
    if check:
        try:
            with open(paths[0]) as f:
                same = f.read() == text
        except OSError as e:
            sys.stderr.write("%s: %s\n" % (name, e))
            return 1
        if not same:
            sys.stderr.write("%s differs from what lib/gen/%s writes; "
                             "regenerate it\n" % (paths[0], name))
            return 1
        print("%s matches the generator" % paths[0])
        return 0
    with open(paths[0], "w") as f:
        f.write(text)
    return 0
