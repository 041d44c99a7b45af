# Print an optspec for argparse to handle cmd's options that are independent of any subcommand.
function __fish_plcsh_global_optspecs
    string join \n c/command= json v/verbose model= d/device= time= config= state= read-only h/help V/version
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
complete -c plcsh -n "__fish_plcsh_needs_command" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_needs_command" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml)' -r -F
complete -c plcsh -n "__fish_plcsh_needs_command" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_needs_command" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_needs_command" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_needs_command" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_needs_command" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_needs_command" -s V -l version -d 'Print version'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "models" -d 'List the K2 model catalogue (areas, I/O, counters, pulse outputs, manual disagreements)'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "devices" -d 'List open devices and the device profiles (devices.toml), with problems in that file'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "completions" -d 'Print a shell completion script (bash, zsh, fish, powershell), or write them all'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "sim" -d 'Serve simulators to other programs: `sim serve` puts the simulated K2 on Modbus TCP / RTU and drives on a pty'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "agent" -d 'The PLC-side helper program that gives plcsh SM registers and instructions on a real K2'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "run" -d 'Run a Lua script: plcsh [--time stepped] [--device NAME=URL] run SCRIPT.lua [ARGS…]'
complete -c plcsh -n "__fish_plcsh_needs_command" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand models" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand devices" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l write -d 'Write every script into DIR (plcsh.bash, _plcsh, plcsh.fish, _plcsh.ps1)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand completions" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve help" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve help" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve help" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve help" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve help" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve help" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve help" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve help" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve help" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve help" -f -a "serve" -d 'Serve the simulator over Modbus TCP, Modbus RTU on a pseudo-terminal, and/or RTU over TCP'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and not __fish_seen_subcommand_from serve help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l tcp -d 'Modbus TCP on ADDR (`127.0.0.1:5020`, `5020`, `0` for a free port; loopback unless a host is given)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l rtu-pty -d 'Modbus RTU on a new pseudo-terminal, with a symlink to its device at LINK' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l rtu-tcp -d 'Modbus RTU frames over TCP on ADDR (as a serial-to-Ethernet gateway carries them)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l unit -d 'Modbus unit id (slave address) the K2 answers to; requests for other ids get no reply' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l agent -d 'Run the PLC-side helper program (lib/k2_agent.il) with its mailbox at this V address' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l servo-pty -d 'Serve simulated Kinco servo drives on a new pseudo-terminal; LINK becomes a symlink to it' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l servo-id -d 'Drive ids on the servo line (several drives share it)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l max-connections -d 'Network connections served at once (per transport); more are closed on accept' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l idle-timeout -d 'Close a network connection that sends nothing for this long (`300s`, `2m`, `500ms`)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l servo-loop -d 'RS232 loop mode: echo every request before the reply (connect with echo=1)'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l strict-unit -d 'On Modbus TCP, answer only the --unit id (by default unit 0xFF is this device too, as libmodbus does)'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from serve" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from help" -f -a "serve" -d 'Serve the simulator over Modbus TCP, Modbus RTU on a pseudo-terminal, and/or RTU over TCP'
complete -c plcsh -n "__fish_plcsh_using_subcommand sim; and __fish_seen_subcommand_from help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il help" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il help" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il help" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il help" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il help" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il help" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il help" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il help" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il help" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il help" -f -a "il" -d 'Print the helper program (K2 instruction list) for KincoBuilder'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and not __fish_seen_subcommand_from il help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l base -d 'Mailbox base: an even V byte address below the E2PROM area (VB3648)' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from il" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from help" -f -a "il" -d 'Print the helper program (K2 instruction list) for KincoBuilder'
complete -c plcsh -n "__fish_plcsh_using_subcommand agent; and __fish_seen_subcommand_from help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l model -d 'Model of the default simulated PLC' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -s d -l device -d 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable' -r
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l time -d 'Simulator time: follow the wall clock, or move only when stepped' -r -f -a "wall\t'Simulator time follows the wall clock'
stepped\t'Simulator time moves only when stepped (`sim step`, waits in scripts)'"
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l config -d 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml)' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l state -d 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user\'s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE' -r -F
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l json -d 'Print one JSON object per command result'
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -s v -l verbose -d 'Show more: each frame sent and received in hex with timing, request counts, sample rates'
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -l read-only -d 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine'
complete -c plcsh -n "__fish_plcsh_using_subcommand run" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices completions sim agent run help" -f -a "models" -d 'List the K2 model catalogue (areas, I/O, counters, pulse outputs, manual disagreements)'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices completions sim agent run help" -f -a "devices" -d 'List open devices and the device profiles (devices.toml), with problems in that file'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices completions sim agent run help" -f -a "completions" -d 'Print a shell completion script (bash, zsh, fish, powershell), or write them all'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices completions sim agent run help" -f -a "sim" -d 'Serve simulators to other programs: `sim serve` puts the simulated K2 on Modbus TCP / RTU and drives on a pty'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices completions sim agent run help" -f -a "agent" -d 'The PLC-side helper program that gives plcsh SM registers and instructions on a real K2'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices completions sim agent run help" -f -a "run" -d 'Run a Lua script: plcsh [--time stepped] [--device NAME=URL] run SCRIPT.lua [ARGS…]'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and not __fish_seen_subcommand_from models devices completions sim agent run help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and __fish_seen_subcommand_from sim" -f -a "serve" -d 'Serve the simulator over Modbus TCP, Modbus RTU on a pseudo-terminal, and/or RTU over TCP'
complete -c plcsh -n "__fish_plcsh_using_subcommand help; and __fish_seen_subcommand_from agent" -f -a "il" -d 'Print the helper program (K2 instruction list) for KincoBuilder'
