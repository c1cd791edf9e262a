#!/bin/bash
# outputs_slow.sh LIFTHULL DATA — the output files' slow cases (tests/cli/outputs.sh has
# the rest): a signal during a large write removes the temporaries and leaves the old
# file; reading and writing show progress on a terminal. Tens of seconds: labelled full.
source "$(dirname "$0")/harness.sh"

"$lh" points --grid 30 -d 2 -o g.txt
notemp() { local t; t=$(find . -name '*.tmp??????'); [ -z "$t" ] && ok || bad "$1: temporaries left: $t"; }
content() { same "$1" "$(head -c 20 "$2")" "$3"; }
old() { for f in "$@"; do echo OLD > "$f"; done; }

# ---- signals: the temporaries go, the old file stays, the signal ends the process --
# SIGXFSZ, deterministic: the write passes the file size limit.
old big.msh
{ (ulimit -f 20; exec "$lh" delaunay g.txt -o big.msh -f) > out.txt 2> err.txt; } 2> /dev/null; rc=$?
same "killed by SIGXFSZ" "$rc" $((128 + 25))
content "big.msh untouched" big.msh OLD; notemp "SIGXFSZ"
# SIGTERM and SIGINT while a large file is written: stopped once its temporary exists.
"$lh" points 200000 -d 3 -o c.txt
for sig in TERM INT; do
  old big.msh
  set -m # a job of its own: SIGINT is not ignored as in a background job without it
  "$lh" delaunay -q c.txt -o big.msh -f 2> err.txt & pid=$!
  set +m
  for _ in $(seq 600); do ls big.msh.tmp?????? > /dev/null 2>&1 && break; sleep 0.05; done
  kill -STOP $pid; kill -$sig $pid; kill -CONT $pid; wait $pid; rc=$?
  if [ "$rc" -eq 0 ]; then echo "SIG$sig came after the file was complete: not checked"; rm -f big.msh; continue; fi
  same "SIG$sig: exit" "$rc" $((128 + $(kill -l $sig)))
  content "SIG$sig: big.msh untouched" big.msh OLD; notemp "SIG$sig"
done

# ---- progress: reading and writing show a line too (on a terminal, after 2 s) -------
# A FIFO fed slowly makes reading take 3 s; one drained slowly, writing (the output
# is larger than a pipe's buffer). `script` gives the command a terminal.
if command -v script > /dev/null; then
  "$lh" points 3000 -d 3 -o p3k.txt
  slow_read() { mkfifo slow.txt; ( printf '3\n4\n0 0 0\n'; sleep 3; printf '1 0 0\n0 1 0\n0 0 1\n' ) > slow.txt & }
  slow_drain() { mkfifo out.fifo; ( exec 3< out.fifo; sleep 3; cat <&3 > /dev/null ) & }
  slow_read; script -qefc "'$lh' delaunay slow.txt -o s.vtu -f" /dev/null > tty.txt; wait; rm -f slow.txt
  grep -q 'lifthull delaunay: reading slow.txt, [23] s' tty.txt && ok || bad "no reading progress: $(cat -v tty.txt)"
  slow_drain; script -qefc "'$lh' delaunay p3k.txt -o out.fifo -f" /dev/null > tty.txt; wait; rm -f out.fifo
  grep -q 'lifthull delaunay: writing out.fifo, [23] s' tty.txt && ok || bad "no writing progress: $(cat -v tty.txt)"
  slow_drain; script -qefc "'$lh' delaunay -q p3k.txt -o out.fifo -f" /dev/null > tty.txt; wait; rm -f out.fifo
  grep -q 'writing' tty.txt && bad "-q: progress shown: $(cat -v tty.txt)" || ok
  slow_read; "$lh" delaunay slow.txt -o s.vtu -f 2> err.txt; wait; rm -f slow.txt
  [ -s err.txt ] && bad "not a terminal: progress shown: $(cat -v err.txt)" || ok
else
  echo "script not found: the progress lines not checked (Debian: util-linux)"
fi

notemp "the end"
finish
