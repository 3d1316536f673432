#!/usr/bin/env bash
# The game in a real window, driven by real X events as a player drives it: xdotool sends them
# through the XTEST extension, so they reach SDL exactly as a keyboard's and mouse's would (the
# replays inject SDL events instead and cannot see this path). Each case starts the game in a
# window on an X server of its own, waits until it plays, sends its events, ends the run with
# SIGTERM (which must end it cleanly and promptly) and reads the `summary` line the game prints.
# The server is private because the suite's is shared: in CI (ctest -j2) another test's window
# took the keyboard focus mid-case and a jump, a reload and an F1 went to it.
# Usage: window_input_test.sh GAME CASE   (cases: taps, ao-cycle, panel-mouse, menu-mouse, menu-click, f12, x-gone)
set -euo pipefail
game=$(realpath "${1:?usage: window_input_test.sh GAME CASE}")
case_name=${2:?usage: window_input_test.sh GAME CASE}
command -v xdotool >/dev/null || { echo "xdotool is missing (scripts/install-deps.sh installs it)"; exit 1; }
command -v Xvfb >/dev/null || { echo "Xvfb is missing (scripts/install-deps.sh installs it)"; exit 1; }
work=$(mktemp -d)
pid=
xvfb_pid=
trap '[ -z "$pid" ] || kill -9 "$pid" 2>/dev/null || true; [ -z "$xvfb_pid" ] || kill "$xvfb_pid" 2>/dev/null || true; rm -rf "$work"' EXIT

own_x() {  # own_x: starts a private Xvfb (the display number it picks itself); sets DISPLAY, xvfb_pid
    exec 3< <(exec Xvfb -displayfd 1 -screen 0 640x480x24 -nolisten tcp 2>/dev/null)
    xvfb_pid=$!
    local number
    read -r -t 30 number <&3 || { echo "no private X server started"; exit 1; }
    export DISPLAY=:$number
}
own_x

# A known view: the courtyard, facing yaw 30, level; long enough a run that only SIGTERM ends it.
start() {  # [W=.. H=..] start [game options...]: sets pid, win, out (320 x 180 unless W, H say)
    out=$work/game.out
    "$game" --width "${W:-320}" --height "${H:-180}" --hud off --ticks 1000000 --start-pose '0 1.65 0 30 0' "$@" >"$out" 2>&1 &
    pid=$!
    win=$(timeout 60 xdotool search --sync --onlyvisible --pid "$pid" | head -1) ||
        { echo "no window appeared:"; cat "$out"; exit 1; }
    # The window opens before the level loads; `level ...` is printed once the scene is built.
    for _ in $(seq 600); do grep -q '^level ' "$out" && break; sleep 0.1; done
    grep -q '^level ' "$out" || { echo "the level never loaded:"; cat "$out"; exit 1; }
    sleep 1  # the first frames (shader compiles)
    xdotool windowfocus --sync "$win"
}

# Every event below is an instant press and release (xdotool sends both at once), so each lands
# inside one frame: the game must latch it on the event, not sample the key at the tick. Taps are
# spaced by TAP seconds, longer than one frame here (under 0.1 s at 320x180 on llvmpipe, more on
# a loaded machine) and than the rifle's 0.1 s between rounds: two clicks inside one frame would
# be one press.
TAP=0.4
settle() { sleep 1.5; }  # lets the last event's frame and tick run before SIGTERM

finish() {  # finish: SIGTERM, then the game must exit 0 within 5 s; sets summary
    local t0 t1
    t0=$(date +%s.%N)
    kill -TERM "$pid"
    local rc=0
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    t1=$(date +%s.%N)
    wait "$pid" || rc=$?
    echo "SIGTERM to exit: $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }') s, exit $rc"
    [ "$rc" -eq 0 ] || { echo "the game exited $rc:"; cat "$out"; exit 1; }
    summary=$(grep '^summary ' "$out") || { echo "no summary line:"; cat "$out"; exit 1; }
    echo "$summary"
}

expect() {  # expect FIELD VALUE: a field of the summary line
    local got
    got=$(echo "$summary" | awk -v k="$1" '{for (i = 1; i < NF; ++i) if ($i == k) print $(i + 1)}')
    if [ "$got" != "$2" ]; then
        echo "FAIL [$case_name]: $1 is '$got', expected '$2'"
        cat "$out"
        exit 1
    fi
}

tap() { xdotool "$@"; sleep "$TAP"; }

case $case_name in
taps)
    start
    # 10 instant clicks fire 10 rounds; then one quick tap each of jump, reload and throw.
    xdotool mousemove --window "$win" 160 90
    for _ in $(seq 10); do tap click 1; done
    tap key space
    tap key r
    tap key g
    settle
    finish
    expect shots 10
    expect jumps 1
    expect reloads 1
    expect grenades 1
    ;;
ao-cycle)
    start
    # O steps forwards, a quick Shift+O (Shift released with the O) backwards: from the default
    # combined, O -> off (it wraps), Shift+O -> combined, Shift+O -> gtao. With Shift lost it
    # would end on hemisphere (combined -> off -> crytek -> hemisphere).
    tap key o
    tap key shift+o
    tap key shift+o
    settle
    finish
    expect ao gtao
    ;;
panel-mouse)
    start --debug-panel
    # While the F1 panel is shown the pointer is the panel's: clicks on it fire nothing and
    # up-and-down motion tilts nothing. Hidden again (F1), the pointer is the game's: sideways
    # motion turns the view (so the pitch check above is not vacuous).
    xdotool mousemove --window "$win" 30 110  # on the panel's text
    for _ in 1 2 3; do tap click 1; done
    xdotool mousemove --window "$win" 30 10
    xdotool mousemove --window "$win" 30 170
    sleep "$TAP"
    tap key F1
    tap mousemove_relative 40 0
    settle
    finish
    expect shots 0
    expect pitch 0.00
    [ "$(echo "$summary" | awk '{for (i = 1; i < NF; ++i) if ($i == "yaw") print $(i + 1)}')" != 30.00 ] ||
        { echo "FAIL [panel-mouse]: the mouse did not turn the view once the panel was hidden"; cat "$out"; exit 1; }
    ;;
menu-mouse)
    start
    # Esc opens the pause menu: it takes pointer and keys; clicks on its title bar fire nothing,
    # motion turns nothing, and Esc closes it again.
    tap key Escape
    xdotool mousemove --window "$win" 60 4
    for _ in 1 2 3; do tap click 1; done
    xdotool mousemove --window "$win" 300 170
    xdotool mousemove --window "$win" 60 4
    sleep "$TAP"
    tap key Escape
    settle
    finish
    expect shots 0
    expect yaw 30.00
    expect pitch 0.00
    ;;
menu-click)
    # An instant click (press and release inside one frame) on the menu's Resume button closes it:
    # ImGui reads the buttons once a frame, so the game holds the release for the next frame. Then
    # a click fires a round, which it would not with the menu still open.
    W=640 H=360 start
    tap key Escape
    xdotool mousemove --window "$win" 178 284  # Resume, as tests/replay/references/pause_menu/menu.png shows it
    sleep "$TAP"                               # the pointer settles (a frame hovers the button)
    tap click 1
    tap click 1
    settle
    finish
    expect shots 1
    ;;
f12)
    # F12 where the game cannot write (/proc, unwritable even for root) costs the picture, not
    # the game: a message and play goes on. Where it can, the PNG is written.
    cd /proc; start; cd - >/dev/null
    tap key F12
    settle
    finish
    grep -q "^obscura: F12 screenshot: cannot write '/proc/obscura-[0-9]*.png': .*; playing on$" "$out" ||
        { echo "FAIL [f12]: no message for the unwritable folder:"; cat "$out"; exit 1; }
    mkdir "$work/shots"
    cd "$work/shots"; start; cd - >/dev/null
    tap key F12
    settle
    finish
    shot=$(ls "$work"/shots/obscura-*.png 2>/dev/null | head -1)
    [ -n "$shot" ] && [ "$(head -c 4 "$shot" | tail -c 3)" = "PNG" ] ||
        { echo "FAIL [f12]: no PNG written:"; cat "$out"; exit 1; }
    # It says where, with the full path (the HUD shows the same line for 2 s).
    grep -q "^screenshot $shot$" "$out" || { echo "FAIL [f12]: no full path of $shot:"; cat "$out"; exit 1; }
    ;;
x-gone)
    # The X server going away mid-run (a crashed or killed Xvfb, a closed SSH forward): one line
    # in the game's words and exit 1, not Xlib's bare "X Error" or "XIO: fatal IO error".
    number=${DISPLAY#:}
    out=$work/game.out
    "$game" --headless --width 160 --height 90 --hud off --ticks 1000000 >"$out" 2>&1 &
    pid=$!
    for _ in $(seq 600); do grep -q '^level ' "$out" && break; sleep 0.1; done
    sleep 1
    kill -9 "$xvfb_pid"
    xvfb_pid=
    rc=0
    wait "$pid" || rc=$?
    pid=
    grep -q '^obscura: lost the connection to the X display (DISPLAY=:'"$number"')' "$out" && [ "$rc" -eq 1 ] ||
        { echo "FAIL [x-gone]: exit $rc, expected 1 with the game's message:"; cat "$out"; exit 1; }
    grep '^obscura: lost' "$out"
    ;;
*)
    echo "unknown case '$case_name'"
    exit 2
    ;;
esac
echo "PASS [$case_name]"
