
using namespace System.Management.Automation
using namespace System.Management.Automation.Language

Register-ArgumentCompleter -Native -CommandName 'plcsh' -ScriptBlock {
    param($wordToComplete, $commandAst, $cursorPosition)

    $commandElements = $commandAst.CommandElements
    $command = @(
        'plcsh'
        for ($i = 1; $i -lt $commandElements.Count; $i++) {
            $element = $commandElements[$i]
            if ($element -isnot [StringConstantExpressionAst] -or
                $element.StringConstantType -ne [StringConstantType]::BareWord -or
                $element.Value.StartsWith('-') -or
                $element.Value -eq $wordToComplete) {
                break
        }
        $element.Value
    }) -join ';'

    $completions = @(switch ($command) {
        'plcsh' {
            [CompletionResult]::new('-c', '-c', [CompletionResultType]::ParameterName, 'Run these commands (separated by `;`) and exit')
            [CompletionResult]::new('--command', '--command', [CompletionResultType]::ParameterName, 'Run these commands (separated by `;`) and exit')
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-f', '-f', [CompletionResultType]::ParameterName, 'Run -c''s commands (or `run`''s script) on every device of this fleet from the profile file, at once (docs/fleets.md)')
            [CompletionResult]::new('--fleet', '--fleet', [CompletionResultType]::ParameterName, 'Run -c''s commands (or `run`''s script) on every device of this fleet from the profile file, at once (docs/fleets.md)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('models', 'models', [CompletionResultType]::ParameterValue, 'List the K2 model catalogue; `models MODEL` shows one in full (areas, counters, manual notes)')
            [CompletionResult]::new('devices', 'devices', [CompletionResultType]::ParameterValue, 'List open devices and the device profiles (devices.toml), with problems in that file')
            [CompletionResult]::new('ports', 'ports', [CompletionResultType]::ParameterValue, 'List the serial ports present, with USB adapter (VID:PID, product, serial number)')
            [CompletionResult]::new('paths', 'paths', [CompletionResultType]::ParameterValue, 'Print where every file lives: profiles, Lua modules, state, history, snapshots, UMPK flash, recordings')
            [CompletionResult]::new('man', 'man', [CompletionResultType]::ParameterValue, 'Print the manual page (roff) made from these flags and the shell''s commands: plcsh man > plcsh.1')
            [CompletionResult]::new('completions', 'completions', [CompletionResultType]::ParameterValue, 'Print a shell completion script (bash, zsh, fish, powershell), or write them all')
            [CompletionResult]::new('sim', 'sim', [CompletionResultType]::ParameterValue, 'Serve simulators to other programs: `sim serve` puts the simulated K2 on Modbus TCP / RTU and drives on a pty or a TCP port (raw or RFC 2217).')
            [CompletionResult]::new('agent', 'agent', [CompletionResultType]::ParameterValue, 'The PLC-side helper program that gives plcsh SM registers and instructions on a real K2')
            [CompletionResult]::new('probe', 'probe', [CompletionResultType]::ParameterValue, 'What a K2 answers over Modbus before the helper is in it: areas and their last addresses, the models that fit, response time; reads only (docs/reference/first-connection.md)')
            [CompletionResult]::new('run', 'run', [CompletionResultType]::ParameterValue, 'Run a Lua script: plcsh [--time stepped] [--device NAME=URL] run SCRIPT.lua [ARGS…]')
            [CompletionResult]::new('record', 'record', [CompletionResultType]::ParameterValue, 'Recordings made with --record: `record show FILE` prints the decoded timeline')
            [CompletionResult]::new('replay', 'replay', [CompletionResultType]::ParameterValue, 'Replay a recording''s requests against a simulator and report every reply that differs')
            [CompletionResult]::new('lab', 'lab', [CompletionResultType]::ParameterValue, 'Teaching labs: `lab new NAME`, `lab check LAB`, `lab grade LAB SUBMISSIONS…` (sandboxed, in parallel)')
            [CompletionResult]::new('publish', 'publish', [CompletionResultType]::ParameterValue, 'Poll operands on a device or a fleet and publish them to an MQTT broker (docs/fleets.md)')
            [CompletionResult]::new('tags', 'tags', [CompletionResultType]::ParameterValue, 'Tag tables (docs/tags.md): `tags FILE` lists the names, `tags check FILE` checks them, `tags export FILE --to csv|iec` writes them in another form')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'plcsh;models' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;devices' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;ports' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;paths' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;man' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;completions' {
            [CompletionResult]::new('--write', '--write', [CompletionResultType]::ParameterName, 'Write every script into DIR (plcsh.bash, _plcsh, plcsh.fish, _plcsh.ps1)')
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;sim' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('serve', 'serve', [CompletionResultType]::ParameterValue, 'Serve the simulator over Modbus TCP, Modbus RTU on a pseudo-terminal, and/or RTU over TCP')
            [CompletionResult]::new('control', 'control', [CompletionResultType]::ParameterValue, 'Send one line to a served simulator''s control channel (faults, events) and print the reply')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'plcsh;sim;serve' {
            [CompletionResult]::new('--tcp', '--tcp', [CompletionResultType]::ParameterName, 'Modbus TCP on ADDR (`127.0.0.1:5020`, `5020`, `0` for a free port; loopback unless a host is given)')
            [CompletionResult]::new('--rtu-pty', '--rtu-pty', [CompletionResultType]::ParameterName, 'Modbus RTU on a new pseudo-terminal, with a symlink to its device at LINK')
            [CompletionResult]::new('--rtu-tcp', '--rtu-tcp', [CompletionResultType]::ParameterName, 'Modbus RTU frames over TCP on ADDR (as a serial-to-Ethernet gateway carries them)')
            [CompletionResult]::new('--unit', '--unit', [CompletionResultType]::ParameterName, 'Modbus unit id (slave address) the K2 answers to; requests for other ids get no reply')
            [CompletionResult]::new('--agent', '--agent', [CompletionResultType]::ParameterName, 'Run the PLC-side helper program (lib/k2_agent.il) with its mailbox at this V address')
            [CompletionResult]::new('--program', '--program', [CompletionResultType]::ParameterName, 'Run this IL program in the served K2 (docs/il.md); load errors stop the server')
            [CompletionResult]::new('--servo-pty', '--servo-pty', [CompletionResultType]::ParameterName, 'Serve simulated Kinco servo drives on a new pseudo-terminal; LINK becomes a symlink to it')
            [CompletionResult]::new('--servo-tcp', '--servo-tcp', [CompletionResultType]::ParameterName, 'Serve simulated Kinco servo drives on a TCP port, as a serial device server would (kinco+tcp://ADDR)')
            [CompletionResult]::new('--servo-control', '--servo-control', [CompletionResultType]::ParameterName, 'The served drive line''s control channel at PATH (default: LINK.ctl beside --servo-pty''s link); clients name it with `control=PATH` (e.g. `kinco+tcp://ADDR?control=PATH`)')
            [CompletionResult]::new('--servo-id', '--servo-id', [CompletionResultType]::ParameterName, 'Drive ids on the servo line (several drives share it)')
            [CompletionResult]::new('--servo-baud', '--servo-baud', [CompletionResultType]::ParameterName, 'Line timing: replies take the frame time at this baud rate (10 bits a byte)')
            [CompletionResult]::new('--servo-latency', '--servo-latency', [CompletionResultType]::ParameterName, 'Line timing: the drive''s think-time before it answers (e.g. 1ms, 0)')
            [CompletionResult]::new('--fx-pty', '--fx-pty', [CompletionResultType]::ParameterName, 'Serve a simulated FX PLC''s programming port on a new pseudo-terminal (symlink at LINK)')
            [CompletionResult]::new('--fx-tcp', '--fx-tcp', [CompletionResultType]::ParameterName, 'Serve the simulated FX PLC''s programming port on a TCP port (fx+tcp://ADDR)')
            [CompletionResult]::new('--fx-link-pty', '--fx-link-pty', [CompletionResultType]::ParameterName, 'Serve the same FX PLC''s computer link (format 1, sum check on) on another pseudo-terminal')
            [CompletionResult]::new('--fx-link-tcp', '--fx-link-tcp', [CompletionResultType]::ParameterName, 'Serve the same FX PLC''s computer link on a TCP port (fxlink+tcp://ADDR)')
            [CompletionResult]::new('--fx-model', '--fx-model', [CompletionResultType]::ParameterName, 'The simulated FX PLC''s model (FX1S, FX1N, FX2N, FX3U; FX2NC and FX3UC name the FX2N and FX3U)')
            [CompletionResult]::new('--fx-station', '--fx-station', [CompletionResultType]::ParameterName, 'The computer link''s station number (0–31)')
            [CompletionResult]::new('--fx-program', '--fx-program', [CompletionResultType]::ParameterName, 'An FX instruction list the simulated FX PLC runs (docs/il.md, "The FX family")')
            [CompletionResult]::new('--umpk-pty', '--umpk-pty', [CompletionResultType]::ParameterName, 'Serve a simulated UMPK teaching PLC on a new pseudo-terminal; LINK becomes a symlink to it')
            [CompletionResult]::new('--umpk-tcp', '--umpk-tcp', [CompletionResultType]::ParameterName, 'Serve a simulated UMPK teaching PLC on a TCP port (umpk+tcp://ADDR)')
            [CompletionResult]::new('--umpk-model', '--umpk-model', [CompletionResultType]::ParameterName, 'The simulated UMPK''s model (UMPK8 or UMPK16)')
            [CompletionResult]::new('--umpk-status-bits', '--umpk-status-bits', [CompletionResultType]::ParameterName, 'Bit numbers of W,H,R,E,P,T in the UMPK''s status word')
            [CompletionResult]::new('--umpk-flash-fail', '--umpk-flash-fail', [CompletionResultType]::ParameterName, 'Make the simulated UMPK''s flash write fail on this 64-byte page (programming gets `W`): 0–31 on the UMPK8, 0–47 on the UMPK16')
            [CompletionResult]::new('--umpk-state', '--umpk-state', [CompletionResultType]::ParameterName, 'Where the simulated UMPK keeps its flash, program info and error history (default: one file per model and link in the user''s data directory; `none` keeps nothing)')
            [CompletionResult]::new('--umpk-program', '--umpk-program', [CompletionResultType]::ParameterName, 'An IL lab program the simulated UMPK runs each 10 ms cycle (docs/il.md, "The UMPK family")')
            [CompletionResult]::new('--fx-control', '--fx-control', [CompletionResultType]::ParameterName, 'The served FX PLC''s control channel at PATH (default: LINK.ctl beside --fx-pty''s link): X inputs switched, a silent line, stuck inputs while clients use its ports')
            [CompletionResult]::new('--umpk-control', '--umpk-control', [CompletionResultType]::ParameterName, 'The served UMPK''s control channel at PATH (default: LINK.ctl beside --umpk-pty''s link): inputs, square waves and faults while the lab''s software uses the line')
            [CompletionResult]::new('--k2-control', '--k2-control', [CompletionResultType]::ParameterName, 'The served K2''s control channel at PATH (default: LINK.ctl beside --rtu-pty''s link): faults added, listed and cleared and the fault event log read while clients poll (`plcsh sim control PATH …`, or `control=PATH` in the client''s URL)')
            [CompletionResult]::new('--fault', '--fault', [CompletionResultType]::ParameterName, 'Inject a fault into the served K2, e.g. `--fault "no-reply on VW100 after=2s times=1"` (repeatable; see `help sim`)')
            [CompletionResult]::new('--max-connections', '--max-connections', [CompletionResultType]::ParameterName, 'Network connections served at once (per transport); more are closed on accept')
            [CompletionResult]::new('--idle-timeout', '--idle-timeout', [CompletionResultType]::ParameterName, 'Close a network connection that sends nothing for this long (`300s`, `2m`, `500ms`)')
            [CompletionResult]::new('--fleet', '--fleet', [CompletionResultType]::ParameterName, 'Serve N simulated K2s, each with its own memory, on N TCP ports (with --tcp: port 0 gives each a free port, port P gives P, P+1, …); the readiness line lists them under `fleet` (docs/fleets.md)')
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--servo-loop', '--servo-loop', [CompletionResultType]::ParameterName, 'RS232 loop mode: echo every request before the reply (connect with echo=1)')
            [CompletionResult]::new('--servo-instant', '--servo-instant', [CompletionResultType]::ParameterName, 'Answer at once instead of at line speed (benchmarks, CI)')
            [CompletionResult]::new('--servo-strict', '--servo-strict', [CompletionResultType]::ParameterName, 'Refuse writes whose size code differs from the object''s (abort 0x06070010)')
            [CompletionResult]::new('--strict-unit', '--strict-unit', [CompletionResultType]::ParameterName, 'On Modbus TCP, answer only the --unit id (by default unit 0xFF is this device too, as libmodbus does)')
            [CompletionResult]::new('--rfc2217', '--rfc2217', [CompletionResultType]::ParameterName, 'The serial options'' TCP ports (--rtu-tcp, --servo-tcp, --fx-tcp, --fx-link-tcp, --umpk-tcp) speak RFC 2217 (Telnet COM-PORT-OPTION) instead of raw TCP: for FAMILY+rfc2217:// and virtual COM port drivers')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;sim;control' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;sim;help' {
            [CompletionResult]::new('serve', 'serve', [CompletionResultType]::ParameterValue, 'Serve the simulator over Modbus TCP, Modbus RTU on a pseudo-terminal, and/or RTU over TCP')
            [CompletionResult]::new('control', 'control', [CompletionResultType]::ParameterValue, 'Send one line to a served simulator''s control channel (faults, events) and print the reply')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'plcsh;sim;help;serve' {
            break
        }
        'plcsh;sim;help;control' {
            break
        }
        'plcsh;sim;help;help' {
            break
        }
        'plcsh;agent' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('il', 'il', [CompletionResultType]::ParameterValue, 'Print the helper program (K2 instruction list) for KincoBuilder')
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Self-test of the helper in a PLC: signature, version, scan rate, system bits, clock and a refused PLS; writes only the mailbox and puts back the SM bytes it used (docs/agent.md)')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'plcsh;agent;il' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'The PLC''s model: the helper runs only the pulse outputs, counters and counter modes this model has (default: the default simulated model)')
            [CompletionResult]::new('--base', '--base', [CompletionResultType]::ParameterName, 'Mailbox base: an even V byte address below the E2PROM area (VB3648)')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;agent;check' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;agent;help' {
            [CompletionResult]::new('il', 'il', [CompletionResultType]::ParameterValue, 'Print the helper program (K2 instruction list) for KincoBuilder')
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Self-test of the helper in a PLC: signature, version, scan rate, system bits, clock and a refused PLS; writes only the mailbox and puts back the SM bytes it used (docs/agent.md)')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'plcsh;agent;help;il' {
            break
        }
        'plcsh;agent;help;check' {
            break
        }
        'plcsh;agent;help;help' {
            break
        }
        'plcsh;probe' {
            [CompletionResult]::new('--report', '--report', [CompletionResultType]::ParameterName, 'Also write the findings as a Markdown report to FILE')
            [CompletionResult]::new('--reads', '--reads', [CompletionResultType]::ParameterName, 'Reads timed for the response time (p50, p99)')
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--scan-serial', '--scan-serial', [CompletionResultType]::ParameterName, 'On a serial line that does not answer, try the common settings (9600…115200 baud, no, even or odd parity) and say which one answered')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;run' {
            [CompletionResult]::new('--write-dir', '--write-dir', [CompletionResultType]::ParameterName, 'With --sandbox: the directory the script may write files in (none without it)')
            [CompletionResult]::new('-f', '-f', [CompletionResultType]::ParameterName, 'Run the script on every device of this fleet at once, each in a Lua state of its own (docs/fleets.md)')
            [CompletionResult]::new('--fleet', '--fleet', [CompletionResultType]::ParameterName, 'Run the script on every device of this fleet at once, each in a Lua state of its own (docs/fleets.md)')
            [CompletionResult]::new('--report', '--report', [CompletionResultType]::ParameterName, 'Write a commissioning report: this HTML file and its JSON twin beside it (docs/commissioning.md). The commission runner writes its checklist there; any other script gets the devices and the log of every write it made')
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--sandbox', '--sandbox', [CompletionResultType]::ParameterName, 'Run a script someone else wrote: no os.execute, io.popen, os.remove/rename/exit, C libraries or debug library; files written only under --write-dir')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;record' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('show', 'show', [CompletionResultType]::ParameterValue, 'Print a recording as a decoded timeline (K2 operand names, servo object names); with --json one object per frame')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'plcsh;record;show' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;record;help' {
            [CompletionResult]::new('show', 'show', [CompletionResultType]::ParameterValue, 'Print a recording as a decoded timeline (K2 operand names, servo object names); with --json one object per frame')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'plcsh;record;help;show' {
            break
        }
        'plcsh;record;help;help' {
            break
        }
        'plcsh;replay' {
            [CompletionResult]::new('--sim-model', '--sim-model', [CompletionResultType]::ParameterName, 'Simulate this K2 model instead of the one each recorded link names')
            [CompletionResult]::new('--snapshot', '--snapshot', [CompletionResultType]::ParameterName, 'Start the simulated K2 from this snapshot (a file, or a name saved with `sim snapshot save`)')
            [CompletionResult]::new('--agent', '--agent', [CompletionResultType]::ParameterName, 'Run the PLC-side helper (lib/k2_agent.il) with its mailbox at this V address. Without it, the helper runs when the recording shows its status block being read')
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;lab' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('new', 'new', [CompletionResultType]::ParameterValue, 'Write a working example lab (K2 + drive with wiring, IL starter, Lua grader) into NAME')
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Check a lab: its lab.toml, files and start state, and the grader on the reference solution')
            [CompletionResult]::new('grade', 'grade', [CompletionResultType]::ParameterValue, 'Grade submissions (files or folders of .lua / .il files), each in a fresh sandboxed worker')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'plcsh;lab;new' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;lab;check' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;lab;grade' {
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'Worker processes at a time (default: one per core)')
            [CompletionResult]::new('--junit', '--junit', [CompletionResultType]::ParameterName, 'Also write the results as JUnit XML to FILE')
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--show-output', '--show-output', [CompletionResultType]::ParameterName, 'Show what each submission printed (stdout and stderr, the first 64 KiB of each); `--json` always carries them as `stdout` and `stderr`')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;lab;help' {
            [CompletionResult]::new('new', 'new', [CompletionResultType]::ParameterValue, 'Write a working example lab (K2 + drive with wiring, IL starter, Lua grader) into NAME')
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Check a lab: its lab.toml, files and start state, and the grader on the reference solution')
            [CompletionResult]::new('grade', 'grade', [CompletionResultType]::ParameterValue, 'Grade submissions (files or folders of .lua / .il files), each in a fresh sandboxed worker')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'plcsh;lab;help;new' {
            break
        }
        'plcsh;lab;help;check' {
            break
        }
        'plcsh;lab;help;grade' {
            break
        }
        'plcsh;lab;help;help' {
            break
        }
        'plcsh;publish' {
            [CompletionResult]::new('--broker', '--broker', [CompletionResultType]::ParameterName, 'The broker: mqtt://HOST:PORT, or mqtts://HOST:PORT for TLS (default: `url` in the profile file''s [mqtt])')
            [CompletionResult]::new('-f', '-f', [CompletionResultType]::ParameterName, 'Publish every member of this fleet (default: the current device)')
            [CompletionResult]::new('--fleet', '--fleet', [CompletionResultType]::ParameterName, 'Publish every member of this fleet (default: the current device)')
            [CompletionResult]::new('--every', '--every', [CompletionResultType]::ParameterName, 'How often each device is read')
            [CompletionResult]::new('--qos', '--qos', [CompletionResultType]::ParameterName, 'MQTT quality of service for values: 0 (at most once) or 1 (at least once)')
            [CompletionResult]::new('--deadband', '--deadband', [CompletionResultType]::ParameterName, 'With --on-change: the smallest change published (in the operand''s units)')
            [CompletionResult]::new('--buffer', '--buffer', [CompletionResultType]::ParameterName, 'Readings queued for the broker at most: while it is away the oldest beyond it are dropped; while it is connected but plcsh falls behind, the newest value of a topic replaces the queued one (both counted)')
            [CompletionResult]::new('--mqtt-version', '--mqtt-version', [CompletionResultType]::ParameterName, 'MQTT protocol version')
            [CompletionResult]::new('--count', '--count', [CompletionResultType]::ParameterName, 'Stop after this many polls of each device (default: until Ctrl-C)')
            [CompletionResult]::new('--client-id', '--client-id', [CompletionResultType]::ParameterName, 'The MQTT client id (default: plcsh-GROUP-PID)')
            [CompletionResult]::new('--shard', '--shard', [CompletionResultType]::ParameterName, 'Publish this part of the fleet only (K of N publishers; default: `shard` in the profile file''s [mqtt])')
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'Model of the default simulated PLC')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--on-change', '--on-change', [CompletionResultType]::ParameterName, 'Publish a value only when it changed (by more than --deadband); otherwise every poll')
            [CompletionResult]::new('--accept-writes', '--accept-writes', [CompletionResultType]::ParameterName, 'Take writes from the broker on plcsh/GROUP/DEVICE/set, only to operands on the device profile''s allow list (replies on plcsh/GROUP/DEVICE/reply); read-only profiles never accept one')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;tags' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'The model whose operands the addresses are (K2, FX or UMPK; default: the simulated K2''s)')
            [CompletionResult]::new('--format', '--format', [CompletionResultType]::ParameterName, 'Read the file as this format instead of telling it by its name and text')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Check a tag file: one line per problem with file:line:column; exit status 1 when there is any')
            [CompletionResult]::new('export', 'export', [CompletionResultType]::ParameterValue, 'Write a tag file in another form (CSV or IEC VAR_GLOBAL) to standard output or --output')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'plcsh;tags;check' {
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'The model whose operands the addresses are (K2, FX or UMPK; default: the simulated K2''s)')
            [CompletionResult]::new('--format', '--format', [CompletionResultType]::ParameterName, 'Read the file as this format instead of telling it by its name and text')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;tags;export' {
            [CompletionResult]::new('--to', '--to', [CompletionResultType]::ParameterName, 'The form to write')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Write here instead of standard output (replaced whole, atomically)')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Write here instead of standard output (replaced whole, atomically)')
            [CompletionResult]::new('--model', '--model', [CompletionResultType]::ParameterName, 'The model whose operands the addresses are (K2, FX or UMPK; default: the simulated K2''s)')
            [CompletionResult]::new('--format', '--format', [CompletionResultType]::ParameterName, 'Read the file as this format instead of telling it by its name and text')
            [CompletionResult]::new('-d', '-d', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--device', '--device', [CompletionResultType]::ParameterName, 'Add a device: NAME=URL, NAME=PROFILE, a bare PROFILE (opened under its name and made current) or a bare URL (which replaces `plc`). Repeatable')
            [CompletionResult]::new('--tags', '--tags', [CompletionResultType]::ParameterName, 'A tag file (CSV, TOML or IEC VAR_GLOBAL) whose names work wherever an operand does: FILE for the current device, DEVICE=FILE for another (docs/tags.md). Repeatable')
            [CompletionResult]::new('--time', '--time', [CompletionResultType]::ParameterName, 'Simulator time: follow the wall clock, or move only when stepped')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Device profile file (default: PLCSH_CONFIG, else ~/.config/plcsh/devices.toml).')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Simulator state file (backup area, retained ranges, clock); default PLCSH_STATE, else in the user''s data directory; `none` reads and writes nothing (labs, tests). `sim serve` keeps state only with --state FILE')
            [CompletionResult]::new('--record', '--record', [CompletionResultType]::ParameterName, 'Record every frame on every device link to FILE (pcapng; `plcsh record show FILE`)')
            [CompletionResult]::new('--bench', '--bench', [CompletionResultType]::ParameterName, 'Open a simulated machine described by a bench file (devices, wiring, initial values)')
            [CompletionResult]::new('-j', '-j', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--jobs', '--jobs', [CompletionResultType]::ParameterName, 'With --fleet: how many devices are worked on at once')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language of messages: en, ru, zh-CN (default: PLCSH_LANG, else the system''s; English when neither names one of these)')
            [CompletionResult]::new('--device-timeout', '--device-timeout', [CompletionResultType]::ParameterName, 'With --fleet: a device still busy after this long is reported as a timeout (`30s`, `2m`; 0 for no limit)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON object per command result')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Show more: each frame sent and received in hex with timing, request counts, sample rates')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Refuse every change to every device (writes, instructions, servo commands): inspect a live machine')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'plcsh;tags;help' {
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Check a tag file: one line per problem with file:line:column; exit status 1 when there is any')
            [CompletionResult]::new('export', 'export', [CompletionResultType]::ParameterValue, 'Write a tag file in another form (CSV or IEC VAR_GLOBAL) to standard output or --output')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'plcsh;tags;help;check' {
            break
        }
        'plcsh;tags;help;export' {
            break
        }
        'plcsh;tags;help;help' {
            break
        }
        'plcsh;help' {
            [CompletionResult]::new('models', 'models', [CompletionResultType]::ParameterValue, 'List the K2 model catalogue; `models MODEL` shows one in full (areas, counters, manual notes)')
            [CompletionResult]::new('devices', 'devices', [CompletionResultType]::ParameterValue, 'List open devices and the device profiles (devices.toml), with problems in that file')
            [CompletionResult]::new('ports', 'ports', [CompletionResultType]::ParameterValue, 'List the serial ports present, with USB adapter (VID:PID, product, serial number)')
            [CompletionResult]::new('paths', 'paths', [CompletionResultType]::ParameterValue, 'Print where every file lives: profiles, Lua modules, state, history, snapshots, UMPK flash, recordings')
            [CompletionResult]::new('man', 'man', [CompletionResultType]::ParameterValue, 'Print the manual page (roff) made from these flags and the shell''s commands: plcsh man > plcsh.1')
            [CompletionResult]::new('completions', 'completions', [CompletionResultType]::ParameterValue, 'Print a shell completion script (bash, zsh, fish, powershell), or write them all')
            [CompletionResult]::new('sim', 'sim', [CompletionResultType]::ParameterValue, 'Serve simulators to other programs: `sim serve` puts the simulated K2 on Modbus TCP / RTU and drives on a pty or a TCP port (raw or RFC 2217).')
            [CompletionResult]::new('agent', 'agent', [CompletionResultType]::ParameterValue, 'The PLC-side helper program that gives plcsh SM registers and instructions on a real K2')
            [CompletionResult]::new('probe', 'probe', [CompletionResultType]::ParameterValue, 'What a K2 answers over Modbus before the helper is in it: areas and their last addresses, the models that fit, response time; reads only (docs/reference/first-connection.md)')
            [CompletionResult]::new('run', 'run', [CompletionResultType]::ParameterValue, 'Run a Lua script: plcsh [--time stepped] [--device NAME=URL] run SCRIPT.lua [ARGS…]')
            [CompletionResult]::new('record', 'record', [CompletionResultType]::ParameterValue, 'Recordings made with --record: `record show FILE` prints the decoded timeline')
            [CompletionResult]::new('replay', 'replay', [CompletionResultType]::ParameterValue, 'Replay a recording''s requests against a simulator and report every reply that differs')
            [CompletionResult]::new('lab', 'lab', [CompletionResultType]::ParameterValue, 'Teaching labs: `lab new NAME`, `lab check LAB`, `lab grade LAB SUBMISSIONS…` (sandboxed, in parallel)')
            [CompletionResult]::new('publish', 'publish', [CompletionResultType]::ParameterValue, 'Poll operands on a device or a fleet and publish them to an MQTT broker (docs/fleets.md)')
            [CompletionResult]::new('tags', 'tags', [CompletionResultType]::ParameterValue, 'Tag tables (docs/tags.md): `tags FILE` lists the names, `tags check FILE` checks them, `tags export FILE --to csv|iec` writes them in another form')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'plcsh;help;models' {
            break
        }
        'plcsh;help;devices' {
            break
        }
        'plcsh;help;ports' {
            break
        }
        'plcsh;help;paths' {
            break
        }
        'plcsh;help;man' {
            break
        }
        'plcsh;help;completions' {
            break
        }
        'plcsh;help;sim' {
            [CompletionResult]::new('serve', 'serve', [CompletionResultType]::ParameterValue, 'Serve the simulator over Modbus TCP, Modbus RTU on a pseudo-terminal, and/or RTU over TCP')
            [CompletionResult]::new('control', 'control', [CompletionResultType]::ParameterValue, 'Send one line to a served simulator''s control channel (faults, events) and print the reply')
            break
        }
        'plcsh;help;sim;serve' {
            break
        }
        'plcsh;help;sim;control' {
            break
        }
        'plcsh;help;agent' {
            [CompletionResult]::new('il', 'il', [CompletionResultType]::ParameterValue, 'Print the helper program (K2 instruction list) for KincoBuilder')
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Self-test of the helper in a PLC: signature, version, scan rate, system bits, clock and a refused PLS; writes only the mailbox and puts back the SM bytes it used (docs/agent.md)')
            break
        }
        'plcsh;help;agent;il' {
            break
        }
        'plcsh;help;agent;check' {
            break
        }
        'plcsh;help;probe' {
            break
        }
        'plcsh;help;run' {
            break
        }
        'plcsh;help;record' {
            [CompletionResult]::new('show', 'show', [CompletionResultType]::ParameterValue, 'Print a recording as a decoded timeline (K2 operand names, servo object names); with --json one object per frame')
            break
        }
        'plcsh;help;record;show' {
            break
        }
        'plcsh;help;replay' {
            break
        }
        'plcsh;help;lab' {
            [CompletionResult]::new('new', 'new', [CompletionResultType]::ParameterValue, 'Write a working example lab (K2 + drive with wiring, IL starter, Lua grader) into NAME')
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Check a lab: its lab.toml, files and start state, and the grader on the reference solution')
            [CompletionResult]::new('grade', 'grade', [CompletionResultType]::ParameterValue, 'Grade submissions (files or folders of .lua / .il files), each in a fresh sandboxed worker')
            break
        }
        'plcsh;help;lab;new' {
            break
        }
        'plcsh;help;lab;check' {
            break
        }
        'plcsh;help;lab;grade' {
            break
        }
        'plcsh;help;publish' {
            break
        }
        'plcsh;help;tags' {
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Check a tag file: one line per problem with file:line:column; exit status 1 when there is any')
            [CompletionResult]::new('export', 'export', [CompletionResultType]::ParameterValue, 'Write a tag file in another form (CSV or IEC VAR_GLOBAL) to standard output or --output')
            break
        }
        'plcsh;help;tags;check' {
            break
        }
        'plcsh;help;tags;export' {
            break
        }
        'plcsh;help;help' {
            break
        }
    })

    $completions.Where{ $_.CompletionText -like "$wordToComplete*" } |
        Sort-Object -Property ListItemText
}
