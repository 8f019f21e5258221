#!/bin/bash
# A vehicle whose ZMODEM is lrzsz, for ZmodemCommandsTest and the end-to-end tests: a shell on
# stdin/stdout (socat puts a pseudo-terminal or a TCP socket in front of it) that reads byte by
# byte, so a lone control key is seen at once, as GliderDOS sees a Control-C at surfacing.
# Ctrl-C answers "Control-C received" and the prompt; Ctrl-R "resuming mission". A line up to CR
# is echoed and run: dir, zs NAME... (sz), zr (rz), anything else "Bad command or file name".
cd "$1" || exit 1
prompt() { printf 'GliderDOS A # >'; }
printf 'Glider sim at surface.\r\n'
prompt
line=
while IFS= read -r -n1 -d '' c; do
  case "$c" in
    $'\003') printf '^C\r\nControl-C received\r\n'; line=; prompt; continue ;;
    $'\022') printf '^R\r\nresuming mission\r\n'; line=; prompt; continue ;;
    $'\n') continue ;;
    $'\r') ;;
    *) line+=$c; continue ;;
  esac
  printf '%s\r\n' "$line"
  set -f
  set -- $line
  set +f
  line=
  case "$1" in
    "") ;;
    dir) for f in *; do
           [ -f "$f" ] && printf '%-12s %10d  11-23-26  02:10\r\n' "$f" "$(stat -c %s "$f")"
         done ;;
    zs) shift; sz -q "$@" 2>/dev/null; printf '\r\n' ;;
    zr) rz -q -y 2>/dev/null; printf '\r\n' ;;
    *) printf 'Bad command or file name\r\n' ;;
  esac
  prompt
done
