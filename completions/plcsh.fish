# Print an optspec for argparse to handle cmd's options that are independent of any subcommand.
function __fish_plcsh_global_optspecs
    string join \n c/command= json v/verbose model= d/device= tags= time= config= state= record= bench= read-only f/fleet= j/jobs= lang= device-timeout= h/help V/version
end

function __fish_plcsh_needs_command
    # Figure out if the current invocation already has a command.
    set -l cmd (commandline -opc)
    set -e cmd[1]
    argparse -s (__fish_plcsh_global_optspecs) -- $cmd 2>/dev/null
    or return
    if set -q argv[1]
        # Also print the command, so this can be used to figure out what it is.
        echo $argv[1]
        return 1
    end
    return 0
end

function __fish_plcsh_using_subcommand
    set -l cmd (__fish_plcsh_needs_command)
    test -z "$cmd"
    and return 1
    contains -- $cmd[1] $argv
end

complete -c plcsh -n "__fish_plcsh_needs_command" -s c -l command -d 'Run these commands (separated by `;`) and exit' -r
complete -c plcsh -n "__fish_plcsh_needs_command" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_needs_command" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_needs_command" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_needs_command" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_needs_command" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_needs_command" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_needs_command" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_needs_command" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_needs_command" -s f -l fleet -d 'Run -c\'s commands (or `run`\'s script) on every device of this fleet from the profile file, at once (docs/fleets.md)' -r
complete -c plcsh -n "__fish_plcsh_needs_command" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_needs_command" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_needs_command" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_needs_command" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_needs_command" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_needs_command" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_needs_command" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_needs_command" -s V -l version -d 'Print version'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "models" -d 'List the K2 model catalogue; `models MODEL` shows one in full (areas, counters, manual notes)'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "devices" -d 'List open devices and the device profiles (devices.toml), with problems in that file'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "ports" -d 'List the serial ports present, with USB adapter (VID:PID, product, serial number)'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "paths" -d 'Print where every file lives: profiles, Lua modules, state, history, snapshots, UMPK flash, recordings'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "man" -d 'Print the manual page (roff) made from these flags and the shell\'s commands: plcsh man > plcsh.1'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "completions" -d 'Print a shell completion script (bash, zsh, fish, powershell), or write them all'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "sim" -d 'Serve simulators to other programs: `sim serve` puts the simulated K2 on Modbus TCP / RTU and drives on a pty or a TCP port (raw or RFC 2217).'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "agent" -d 'The PLC-side helper program that gives plcsh SM registers and instructions on a real K2'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "probe" -d 'What a K2 answers over Modbus before the helper is in it: areas and their last addresses, the models that fit, response time; reads only (docs/reference/first-connection.md)'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "run" -d 'Run a Lua script: plcsh [--time stepped] [--device NAME=URL] run SCRIPT.lua [ARGS…]'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "record" -d 'Recordings made with --record: `record show FILE` prints the decoded timeline'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "replay" -d 'Replay a recording\'s requests against a simulator and report every reply that differs'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "lab" -d 'Teaching labs: `lab new NAME`, `lab check LAB`, `lab grade LAB SUBMISSIONS…` (sandboxed, in parallel)'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "publish" -d 'Poll operands on a device or a fleet and publish them to an MQTT broker (docs/fleets.md)'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "tags" -d 'Tag tables (docs/tags.md): `tags FILE` lists the names, `tags check FILE` checks them, `tags export FILE --to csv|iec` writes them in another form'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand ports" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand paths" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand man" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l write -d 'Write every script into DIR (plcsh.bash, _plcsh, plcsh.fish, _plcsh.ps1)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -f -a "serve" -d 'Serve the simulator over Modbus TCP, Modbus RTU on a pseudo-terminal, and/or RTU over TCP'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -f -a "control" -d 'Send one line to a served simulator\'s control channel (faults, events) and print the reply'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve control help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l tcp -d 'Modbus TCP on ADDR (`127.0.0.1:5020`, `5020`, `0` for a free port; loopback unless a host is given)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l rtu-pty -d 'Modbus RTU on a new pseudo-terminal, with a symlink to its device at LINK' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l rtu-tcp -d 'Modbus RTU frames over TCP on ADDR (as a serial-to-Ethernet gateway carries them)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l unit -d 'Modbus unit id (slave address) the K2 answers to; requests for other ids get no reply' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l agent -d 'Run the PLC-side helper program (lib/k2_agent.il) with its mailbox at this V address' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l program -d 'Run this IL program in the served K2 (docs/il.md); load errors stop the server' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l servo-pty -d 'Serve simulated Kinco servo drives on a new pseudo-terminal; LINK becomes a symlink to it' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l servo-tcp -d 'Serve simulated Kinco servo drives on a TCP port, as a serial device server would (kinco+tcp://ADDR)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l servo-control -d 'The served drive line\'s control channel at PATH (default: LINK.ctl beside --servo-pty\'s link); clients name it with `control=PATH` (e.g. `kinco+tcp://ADDR?control=PATH`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l servo-id -d 'Drive ids on the servo line (several drives share it)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l servo-baud -d 'Line timing: replies take the frame time at this baud rate (10 bits a byte)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l servo-latency -d 'Line timing: the drive\'s think-time before it answers (e.g. 1ms, 0)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l fx-pty -d 'Serve a simulated FX PLC\'s programming port on a new pseudo-terminal (symlink at LINK)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l fx-tcp -d 'Serve the simulated FX PLC\'s programming port on a TCP port (fx+tcp://ADDR)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l fx-link-pty -d 'Serve the same FX PLC\'s computer link (format 1, sum check on) on another pseudo-terminal' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l fx-link-tcp -d 'Serve the same FX PLC\'s computer link on a TCP port (fxlink+tcp://ADDR)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l fx-model -d 'The simulated FX PLC\'s model (FX1S, FX1N, FX2N, FX3U; FX2NC and FX3UC name the FX2N and FX3U)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l fx-station -d 'The computer link\'s station number (0–31)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l fx-program -d 'An FX instruction list the simulated FX PLC runs (docs/il.md, "The FX family")' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l umpk-pty -d 'Serve a simulated UMPK teaching PLC on a new pseudo-terminal; LINK becomes a symlink to it' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l umpk-tcp -d 'Serve a simulated UMPK teaching PLC on a TCP port (umpk+tcp://ADDR)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l umpk-model -d 'The simulated UMPK\'s model (UMPK8 or UMPK16)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l umpk-status-bits -d 'Bit numbers of W,H,R,E,P,T in the UMPK\'s status word' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l umpk-flash-fail -d 'Make the simulated UMPK\'s flash write fail on this 64-byte page (programming gets `W`): 0–31 on the UMPK8, 0–47 on the UMPK16' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l umpk-state -d 'Where the simulated UMPK keeps its flash, program info and error history (default: one file per model and link in the user\'s data directory; `none` keeps nothing)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l umpk-program -d 'An IL lab program the simulated UMPK runs each 10 ms cycle (docs/il.md, "The UMPK family")' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l fx-control -d 'The served FX PLC\'s control channel at PATH (default: LINK.ctl beside --fx-pty\'s link): X inputs switched, a silent line, stuck inputs while clients use its ports' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l umpk-control -d 'The served UMPK\'s control channel at PATH (default: LINK.ctl beside --umpk-pty\'s link): inputs, square waves and faults while the lab\'s software uses the line' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l k2-control -d 'The served K2\'s control channel at PATH (default: LINK.ctl beside --rtu-pty\'s link): faults added, listed and cleared and the fault event log read while clients poll (`plcsh sim control PATH …`, or `control=PATH` in the client\'s URL)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l fault -d 'Inject a fault into the served K2, e.g. `--fault "no-reply on VW100 after=2s times=1"` (repeatable; see `help sim`)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l max-connections -d 'Network connections served at once (per transport); more are closed on accept' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l idle-timeout -d 'Close a network connection that sends nothing for this long (`300s`, `2m`, `500ms`)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l fleet -d 'Serve N simulated K2s, each with its own memory, on N TCP ports (with --tcp: port 0 gives each a free port, port P gives P, P+1, …); the readiness line lists them under `fleet` (docs/fleets.md)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l servo-loop -d 'RS232 loop mode: echo every request before the reply (connect with echo=1)'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l servo-instant -d 'Answer at once instead of at line speed (benchmarks, CI)'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l servo-strict -d 'Refuse writes whose size code differs from the object\'s (abort 0x06070010)'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l strict-unit -d 'On Modbus TCP, answer only the --unit id (by default unit 0xFF is this device too, as libmodbus does)'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l rfc2217 -d 'The serial options\' TCP ports (--rtu-tcp, --servo-tcp, --fx-tcp, --fx-link-tcp, --umpk-tcp) speak RFC 2217 (Telnet COM-PORT-OPTION) instead of raw TCP: for FAMILY+rfc2217:// and virtual COM port drivers'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from control" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from help" -f -a "serve" -d 'Serve the simulator over Modbus TCP, Modbus RTU on a pseudo-terminal, and/or RTU over TCP'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from help" -f -a "control" -d 'Send one line to a served simulator\'s control channel (faults, events) and print the reply'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -f -a "il" -d 'Print the helper program (K2 instruction list) for KincoBuilder'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -f -a "check" -d 'Self-test of the helper in a PLC: signature, version, scan rate, system bits, clock and a refused PLS; writes only the mailbox and puts back the SM bytes it used (docs/agent.md)'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il check help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l model -d 'The PLC\'s model: the helper runs only the pulse outputs, counters and counter modes this model has (default: the default simulated model)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l base -d 'Mailbox base: an even V byte address below the E2PROM area (VB3648)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from check" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from help" -f -a "il" -d 'Print the helper program (K2 instruction list) for KincoBuilder'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from help" -f -a "check" -d 'Self-test of the helper in a PLC: signature, version, scan rate, system bits, clock and a refused PLS; writes only the mailbox and puts back the SM bytes it used (docs/agent.md)'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l report -d 'Also write the findings as a Markdown report to FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l reads -d 'Reads timed for the response time (p50, p99)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l scan-serial -d 'On a serial line that does not answer, try the common settings (9600…115200 baud, no, even or odd parity) and say which one answered'
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand probe" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l write-dir -d 'With --sandbox: the directory the script may write files in (none without it)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -s f -l fleet -d 'Run the script on every device of this fleet at once, each in a Lua state of its own (docs/fleets.md)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l report -d 'Write a commissioning report: this HTML file and its JSON twin beside it (docs/commissioning.md). The commission runner writes its checklist there; any other script gets the devices and the log of every write it made' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l sandbox -d 'Run a script someone else wrote: no os.execute, io.popen, os.remove/rename/exit, C libraries or debug library; files written only under --write-dir'
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -f -a "show" -d 'Print a recording as a decoded timeline (K2 operand names, servo object names); with --json one object per frame'
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and not __fish_seen_subcommand_from show help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from show" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from help" -f -a "show" -d 'Print a recording as a decoded timeline (K2 operand names, servo object names); with --json one object per frame'
complete -c plcsh -n "__fish_plcsh_using_subcommand record; and __fish_seen_subcommand_from help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l sim-model -d 'Simulate this K2 model instead of the one each recorded link names' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l snapshot -d 'Start the simulated K2 from this snapshot (a file, or a name saved with `sim snapshot save`)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l agent -d 'Run the PLC-side helper (lib/k2_agent.il) with its mailbox at this V address. Without it, the helper runs when the recording shows its status block being read' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand replay" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -f -a "new" -d 'Write a working example lab (K2 + drive with wiring, IL starter, Lua grader) into NAME'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -f -a "check" -d 'Check a lab: its lab.toml, files and start state, and the grader on the reference solution'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -f -a "grade" -d 'Grade submissions (files or folders of .lua / .il files), each in a fresh sandboxed worker'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and not __fish_seen_subcommand_from new check grade help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from new" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from check" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l jobs -d 'Worker processes at a time (default: one per core)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l junit -d 'Also write the results as JUnit XML to FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l show-output -d 'Show what each submission printed (stdout and stderr, the first 64 KiB of each); `--json` always carries them as `stdout` and `stderr`'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from grade" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from help" -f -a "new" -d 'Write a working example lab (K2 + drive with wiring, IL starter, Lua grader) into NAME'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from help" -f -a "check" -d 'Check a lab: its lab.toml, files and start state, and the grader on the reference solution'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from help" -f -a "grade" -d 'Grade submissions (files or folders of .lua / .il files), each in a fresh sandboxed worker'
complete -c plcsh -n "__fish_plcsh_using_subcommand lab; and __fish_seen_subcommand_from help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l broker -d 'The broker: mqtt://HOST:PORT, or mqtts://HOST:PORT for TLS (default: `url` in the profile file\'s [mqtt])' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -s f -l fleet -d 'Publish every member of this fleet (default: the current device)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l every -d 'How often each device is read' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l qos -d 'MQTT quality of service for values: 0 (at most once) or 1 (at least once)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l deadband -d 'With --on-change: the smallest change published (in the operand\'s units)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l buffer -d 'Readings queued for the broker at most: while it is away the oldest beyond it are dropped; while it is connected but plcsh falls behind, the newest value of a topic replaces the queued one (both counted)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l mqtt-version -d 'MQTT protocol version' -r -f -a "3.1.1\t''
5\t''"
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l count -d 'Stop after this many polls of each device (default: until Ctrl-C)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l client-id -d 'The MQTT client id (default: plcsh-GROUP-PID)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l shard -d 'Publish this part of the fleet only (K of N publishers; default: `shard` in the profile file\'s [mqtt])' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l on-change -d 'Publish a value only when it changed (by more than --deadband); otherwise every poll'
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l accept-writes -d 'Take writes from the broker on plcsh/GROUP/DEVICE/set, only to operands on the device profile\'s allow list (replies on plcsh/GROUP/DEVICE/reply); read-only profiles never accept one'
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand publish" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -l model -d 'The model whose operands the addresses are (K2, FX or UMPK; default: the simulated K2\'s)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -l format -d 'Read the file as this format instead of telling it by its name and text' -r -f -a "csv\t''
toml\t''
iec\t''"
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -a "check" -d 'Check a tag file: one line per problem with file:line:column; exit status 1 when there is any'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -a "export" -d 'Write a tag file in another form (CSV or IEC VAR_GLOBAL) to standard output or --output'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and not __fish_seen_subcommand_from check export help" -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -l model -d 'The model whose operands the addresses are (K2, FX or UMPK; default: the simulated K2\'s)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -l format -d 'Read the file as this format instead of telling it by its name and text' -r -f -a "csv\t''
toml\t''
iec\t''"
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from check" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -l to -d 'The form to write' -r -f -a "csv\t''
iec\t''"
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -s o -l output -d 'Write here instead of standard output (replaced whole, atomically)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -l model -d 'The model whose operands the addresses are (K2, FX or UMPK; default: the simulated K2\'s)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -l format -d 'Read the file as this format instead of telling it by its name and text' -r -f -a "csv\t''
toml\t''
iec\t''"
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -l tags -d 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -l record -d 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -l bench -d 'Open a simulated machine described by a bench file (devices, wiring, initial values)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -s j -l jobs -d 'With --fleet: how many devices are worked on at once' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -l lang -d 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system\'s; English when neither names one of these)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -l device-timeout -d 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from export" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from help" -f -a "check" -d 'Check a tag file: one line per problem with file:line:column; exit status 1 when there is any'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from help" -f -a "export" -d 'Write a tag file in another form (CSV or IEC VAR_GLOBAL) to standard output or --output'
complete -c plcsh -n "__fish_plcsh_using_subcommand tags; and __fish_seen_subcommand_from help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "models" -d 'List the K2 model catalogue; `models MODEL` shows one in full (areas, counters, manual notes)'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "devices" -d 'List open devices and the device profiles (devices.toml), with problems in that file'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "ports" -d 'List the serial ports present, with USB adapter (VID:PID, product, serial number)'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "paths" -d 'Print where every file lives: profiles, Lua modules, state, history, snapshots, UMPK flash, recordings'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "man" -d 'Print the manual page (roff) made from these flags and the shell\'s commands: plcsh man > plcsh.1'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "completions" -d 'Print a shell completion script (bash, zsh, fish, powershell), or write them all'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "sim" -d 'Serve simulators to other programs: `sim serve` puts the simulated K2 on Modbus TCP / RTU and drives on a pty or a TCP port (raw or RFC 2217).'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "agent" -d 'The PLC-side helper program that gives plcsh SM registers and instructions on a real K2'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "probe" -d 'What a K2 answers over Modbus before the helper is in it: areas and their last addresses, the models that fit, response time; reads only (docs/reference/first-connection.md)'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "run" -d 'Run a Lua script: plcsh [--time stepped] [--device NAME=URL] run SCRIPT.lua [ARGS…]'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "record" -d 'Recordings made with --record: `record show FILE` prints the decoded timeline'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "replay" -d 'Replay a recording\'s requests against a simulator and report every reply that differs'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "lab" -d 'Teaching labs: `lab new NAME`, `lab check LAB`, `lab grade LAB SUBMISSIONS…` (sandboxed, in parallel)'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "publish" -d 'Poll operands on a device or a fleet and publish them to an MQTT broker (docs/fleets.md)'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "tags" -d 'Tag tables (docs/tags.md): `tags FILE` lists the names, `tags check FILE` checks them, `tags export FILE --to csv|iec` writes them in another form'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices ports paths man completions sim agent probe run record replay lab publish tags help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and __fish_seen_subcommand_from sim" -f -a "serve" -d 'Serve the simulator over Modbus TCP, Modbus RTU on a pseudo-terminal, and/or RTU over TCP'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and __fish_seen_subcommand_from sim" -f -a "control" -d 'Send one line to a served simulator\'s control channel (faults, events) and print the reply'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and __fish_seen_subcommand_from agent" -f -a "il" -d 'Print the helper program (K2 instruction list) for KincoBuilder'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and __fish_seen_subcommand_from agent" -f -a "check" -d 'Self-test of the helper in a PLC: signature, version, scan rate, system bits, clock and a refused PLS; writes only the mailbox and puts back the SM bytes it used (docs/agent.md)'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and __fish_seen_subcommand_from record" -f -a "show" -d 'Print a recording as a decoded timeline (K2 operand names, servo object names); with --json one object per frame'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and __fish_seen_subcommand_from lab" -f -a "new" -d 'Write a working example lab (K2 + drive with wiring, IL starter, Lua grader) into NAME'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and __fish_seen_subcommand_from lab" -f -a "check" -d 'Check a lab: its lab.toml, files and start state, and the grader on the reference solution'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and __fish_seen_subcommand_from lab" -f -a "grade" -d 'Grade submissions (files or folders of .lua / .il files), each in a fresh sandboxed worker'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and __fish_seen_subcommand_from tags" -f -a "check" -d 'Check a tag file: one line per problem with file:line:column; exit status 1 when there is any'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and __fish_seen_subcommand_from tags" -f -a "export" -d 'Write a tag file in another form (CSV or IEC VAR_GLOBAL) to standard output or --output'
