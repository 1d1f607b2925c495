"""embedded_report.py: the Markdown report of scripts/embedded_check.py (its measurements in,
embedded.md out); kept apart so that the check reads as the steps it runs."""

import os


def compared(r):
    """A replay's comparison with pamsim's commands, in words."""
    if r["equal"]:
        return f"equal ({r['ticks']} ticks)"
    return f"differs from tick {r['tick']} (largest {r['largest_pa']:.6g} Pa)"


def closest(found):
    units = {"Ia": "v_thr", "Ib": "f_thr"}
    return "; ".join(
        f"{k}: {v:.3g} {'mm/s' if k == 'Ia' else 'N'} from {units[k]}" for k, v in found.items()
    )


def trials_table(trials):
    lines = [
        "| trial | reflexes | muscles | gcc, double | clang, double | gcc and clang "
        "replays' outputs | float: largest difference of a command [kPa], of v [mm/s] | "
        "float triggers | "
        "closest approach to a threshold in double |",
        "|" + " --- |" * 9,
    ]
    for t in trials:
        fd = t["float_vs_double"]
        n = len(fd["differing"])
        same = "the same" if not n else f"differ at {n} tick{'s' if n > 1 else ''}"
        lines.append(
            f"| {t['scenario']} ({t['what']}) | {t['reflexes']} | {t['muscles']} | "
            f"{compared(t['gcc'])} | {compared(t['clang'])} | "
            f"{'identical' if t['gcc_is_clang'] else 'differ'} | "
            f"{fd['largest_kpa']:.4g}, {fd['velocity_mm_s']:.3g} | "
            f"{same} ({fd['double_triggers']} in double) | {closest(fd['closest'])} |"
        )
    notes = [
        f"- {t['scenario']} ({t['what']}): {d['kind']} trigger of {d['muscle']} at tick "
        f"{d['tick']} (t = {d['time_s']:.6g} s) in the {d['in']} build only; in double, "
        f"{d['margin']}"
        for t in trials
        for d in t["float_vs_double"]["differing"]
    ]
    return "\n".join(lines + ([""] + notes if notes else []))


def boards_table(boards, arm_flags):
    lines = [
        "| processor | precision | muscles (MAX_MUSCLES) | flash: libpamctl.a text+data [B] "
        "| RAM: libpamctl.a data+bss [B] | RAM: the board's state, example_loop.o .bss "
        "[B] | stack: pamctl_tick, deepest path [B] |",
        "|" + " --- |" * 7,
    ]
    paths = []
    for b in boards:
        head = f"| {b['processor']} | {b['precision']} | {b['max_muscles']} ({b['trial']}) |"
        if "error" in b:
            lines.append(head + " build failed | | | |")
            paths.append(
                f"- {b['processor']} {b['precision']}, {b['max_muscles']} muscles: {b['error']}"
            )
            continue
        lines.append(head + f" {b['flash']} | {b['lib_ram']} | {b['state_ram']} | {b['stack']} |")
        chain = " -> ".join(
            f"{n} {s}" if s is not None else f"{n} (external)" for n, s in b["path"]
        )
        dynamic = f" (frames of {', '.join(b['dynamic'])} size)" if b["dynamic"] else ""
        paths.append(
            f"- {b['processor']} {b['precision']}, {b['max_muscles']} muscles: {chain}{dynamic}"
        )
    flags = "; ".join(f"{p}: `{f}`" for p, f in arm_flags.items())
    return "\n".join(
        lines
        + ["", "Deepest call chains from pamctl_tick (bytes per frame):", ""]
        + paths
        + [
            "",
            f"Flags: {flags}, with the export's own (`-O2 -std=c99 "
            "-Werror`, no fused multiply-add).",
        ]
    )


def write_report(path, trials, user, boards, qemu, versions, arm_flags):
    """Writes embedded.md (its section titles as bold lines, as a docs block shows them);
    returns whether every double build's commands equal pamsim's and
    every build ran."""
    doubles = [t[b] for t in trials for b in ("gcc", "clang")]
    doubles += [user["make"], user["make_clang"], user["cmake"], qemu]
    passed = all(r["equal"] for r in doubles) and not any("error" in b for b in boards)
    tuned = ", ".join(f"reflex.{k} = {v:.6g}" for k, v in user["tuned"].items())
    first = qemu.get("first_column")
    where = f"; first differing output: {first[1]} at tick {first[0]}" if first else ""
    tools = ", ".join(f"{k} {v}" for k, v in versions.items())
    text = f"""**The exported controller against pamsim**

{
        "Every double build's commands equal pamsim's bit for bit."
        if passed
        else "FAILED: a build failed, or a double build's commands differ from pamsim's (below)."
    } Tools: {tools}.

**Each trial, built on the host**

Each trial's `pamsim run --readings`, its `pamsim controller export` built with the export's
Makefile, and `build/pamctl_replay readings.csv` compared with the commands pamsim sent. The
float build is compared with the gcc double build; the closest approach is the double build's
smallest distance of any muscle's v (Ia) or Eq. (9) tension (Ib) from its threshold over the
trial, which rounding would have to cross to move a trigger.

{trials_table(trials)}

**A user's build**

The export of {user["scenario"]}{f" ({tuned})" if tuned else ""}, built in its
folder with `make` (gcc, and `CC=clang`) and with `cmake -S . -B cmake-build`:

| build | commands against pamsim's |
| --- | --- |
| make (gcc) | {compared(user["make"])} |
| make CC=clang | {compared(user["make_clang"])} |
| CMake | {compared(user["cmake"])} |

**Microcontrollers**

`make lib CC=arm-none-eabi-gcc` with `-fstack-usage -fcallgraph-info=su`. Flash and RAM are
the library's (the configuration included); the board's state is the configuration, state,
input and output the example loop keeps in static storage. libm's sqrt and cbrt (sqrtf,
cbrtf in float) and memset are external: neither their code nor their stack is counted.

{boards_table(boards, arm_flags)}

**Another processor**

| processor | build | drop_mass.toml's commands against pamsim's |
| --- | --- | --- |
| ARMv7-A Linux under qemu-arm | arm-linux-gnueabihf-gcc, double, static | {compared(qemu)}{where} |
"""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)
    return passed
