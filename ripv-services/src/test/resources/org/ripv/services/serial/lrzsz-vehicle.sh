#!/bin/bash
# A vehicle whose YMODEM is lrzsz, for LrzszCleanLineTest: a PicoDOS-like shell on stdin/stdout
# (socat puts a pseudo-terminal in front of it). It reads a line up to CR, echoes it, runs it, and
# prints its prompt. Like a real shell it takes any byte left in its input as part of the next
# line: a receiver's late 'C' turns "yr" into "Cyr", which it refuses.
# With REFUSE_ONCE set it refuses the first ys and the first yr it gets, as that vehicle did.
# With STRAY set, a 'C' is left in its input after every ys, as a receiver's late 'C' would be.
cd "$1" || exit 1
printf 'lrzsz vehicle\r\nC:\\>'
pending=
while IFS= read -r -d $'\r' line; do
  line=$pending${line#$'\n'}
  pending=
  printf '%s\r\n' "$line"
  set -f
  set -- $line
  set +f
  if [ -n "$REFUSE_ONCE" ] && { { [ "$1" = ys ] && [ -z "$refused_ys" ]; } || { [ "$1" = yr ] && [ -z "$refused_yr" ]; }; }; then
    printf -v "refused_$1" 1
    set -- "C$1"
  fi
  case "$1" in
    "") ;;
    dir) for f in *; do
           [ -f "$f" ] && printf '%-12s %10d  11-23-26  02:10\r\n' "$f" "$(stat -c %s "$f")"
         done ;;
    ys) shift; sb --ymodem -k -q "$@" 2>/dev/null; printf '\r\n'; [ -n "$STRAY" ] && pending=C ;;
    yr) rb --ymodem -y -u -q 2>/dev/null; printf '\r\n' ;;
    *) printf 'Bad command or file name\r\n' ;;
  esac
  printf 'C:\\>'
done
