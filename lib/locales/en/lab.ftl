# plcsh messages (en): lab — labs, scripts and recordings. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## Limits of a graded run (core::budget): the verdict names the limit passed.
budget-exceeded-minutes = exceeded { $n ->
    [one] { $n } simulated minute
   *[other] { $n } simulated minutes
}
budget-exceeded-seconds = exceeded { $n ->
    [one] { $n } simulated second
   *[other] { $n } simulated seconds
}
budget-exceeded-instructions = exceeded { $count } Lua instructions
budget-exceeded-memory = exceeded { $size } of Lua memory
budget-size-mib = { $n } MiB
budget-size-bytes = { $n } bytes

## Verdicts of a graded submission (lab::grader, lab::runner).
lab-grader-error = grader error: { $error }
lab-runtime-error = runtime error: { $error }
lab-exceeded-write = exceeded { $size } in the write directory
lab-exceeded-wall = exceeded the wall-clock safety net of { $seconds } s
lab-not-graded = not graded: stopped by { $cause }
lab-refused-link = refused: { $file } is a symbolic link: a submission is its own files, never a link (hand in the file itself)
lab-refused-size = refused: the submission is { $n } bytes, more than the lab's { $cap } ([budget] submission in lab.toml)
lab-not-submission-kind = not a submission: give a .lua script or an .il program
lab-not-submission-missing = not a submission: no such file
lab-not-accepted = not accepted: this lab accepts { $kinds } submissions
lab-plc-stopped = { $file }:{ $line }: the PLC stopped: { $error }
lab-plc-fault-code-at = { $place }: the PLC stopped on fault { $code } ({ $kind }): { $error } at `{ $at }`
lab-plc-fault-code = { $place }: the PLC stopped on fault { $code } ({ $kind }): { $error }
lab-plc-fault-at = { $place }: the PLC stopped on ({ $kind }): { $error } at `{ $at }`
lab-plc-fault = { $place }: the PLC stopped on ({ $kind }): { $error }
lab-device-replaced = { $file }: the submission closed or replaced the lab's device `{ $device }`
lab-cannot-read = cannot read { $file }: { $error }
lab-cannot-start-lua = cannot start Lua: { $error }
lab-opening-devices = opening the lab's devices
lab-view = the submission's own files, the lab's shared and starter files and the write directory
lab-write-dir-role = the write directory
lab-cannot-create-write-dir = cannot create a write directory for the run
lab-write-dir-not-own = the write directory given is not a folder of the grader's own
lab-cannot-create-report-dir = cannot create a folder for the report: { $error }
lab-cannot-create-write-dir-error = cannot create the write directory: { $error }
lab-cannot-start-worker = cannot start a worker: { $error }
lab-worker-no-report = the worker ended ({ $status }) without a report
lab-worker-error = plcsh lab worker: { $error }
lab-worker-cannot-write = plcsh lab worker: cannot write { $file }: { $error }
lab-workers-running = workers still running
lab-no-executable = cannot find the plcsh executable
lab-bytes-more = … { $n } bytes more

## `lab grade`, `lab new`, `lab check` (lab::runner, lab, cli::lab, shell::commands::lab).
lab-cannot-list = cannot list { $dir }
lab-no-such-submission = { $file }: no such file or folder
lab-hint-submissions = give submission files (.lua, .il) or folders of them
lab-no-submissions = no submissions found (.lua or .il files)
lab-grade-stopped = lab grade stopped by { $cause } before every submission was graded ({ $done } graded)
lab-hint-grade-again = run it again to grade every submission
lab-cannot-write = cannot write { $file }
lab-new-exists = { $dir } already exists
lab-hint-new-name = give a new folder name: plcsh lab new NAME
lab-cannot-create = cannot create { $dir }
lab-cannot-create-empty-dir = cannot create a folder for the empty program
lab-cannot-write-empty = cannot write the empty program
lab-not-in-sandbox = `lab` is not available in a sandboxed run (it starts processes and writes folders)
lab-not-in-this-run = `lab` is not available in this run
lab-hint-check-table = the table from `plcsh lab check` names each criterion's result
lab-bad-jobs = jobs={ $jobs }: a number of workers ≥ 1
lab-needs-sub = `lab` needs new, check or grade with its arguments

## lab.toml (lab::config).
lab-cannot-read-file = cannot read { $file }
lab-hint-lab-folder = a lab is a folder with a lab.toml; `plcsh lab new NAME` writes an example
lab-cannot-open = cannot open { $dir }
lab-no-such-file = { $file }: { $key } = "{ $name }": no such file in { $dir }
lab-file-outside = { $file }: { $key } = "{ $name }" is outside the lab folder
lab-hint-files-inside = a lab's files live in its folder, so the lab can be copied whole
lab-devices-one-way = { $file }: give the devices as bench = "FILE" or as a [devices] table (one of the two)
lab-hint-devices-example = e.g. [devices] plc = "sim:K205-16DT"
lab-budget-not-time = { $file }: [budget] { $key } = "{ $text }" is not a time plcsh reads
lab-budget-not-time-why = { $file }: [budget] { $key } = "{ $text }" is not a time plcsh reads: { $error }
lab-hint-write-time = write "{ $time }" (units h, min, s, ms)
lab-hint-write-time-or = write "{ $time }" or "{ $seconds }" (units h, min, s, ms)
lab-hint-time-example = e.g. "10min", "90s", "1h" (units h, min, s, ms)
lab-budget-not-positive = { $file }: [budget] { $key } = "{ $text }" must be more than zero
lab-budget-not-size = { $file }: [budget] { $key } = "{ $text }" is not a size
lab-hint-write-size = write "{ $size }" (units B, KiB, MiB, GiB)
lab-hint-size-example = e.g. "256MiB" (units B, KiB, MiB, GiB)
lab-budget-instructions-zero = { $file }: [budget] instructions must be more than zero
lab-not-a-grant = { $file }: grants = ["{ $grant }"]: not an action a lab grants
lab-hint-did-you-mean-grant = did you mean "{ $near }"? grants: { $grants }
lab-hint-grants = grants: { $grants }
lab-points-negative = { $file }: [points] "{ $key }" = { $value }: points are a number ≥ 0
lab-not-a-device = { $file }: device = "{ $device }" is not a device of the lab
lab-hint-did-you-mean-device = did you mean device = "{ $near }"? the lab's devices: { $devices }
lab-hint-devices = the lab's devices: { $devices }
lab-not-a-kind = { $file }: accepts = ["{ $kind }"]: not a submission kind
lab-hint-kinds = kinds: { $kinds }
lab-shared-not-lua = { $file }: shared = ["{ $name }"]: a shared module is a .lua file
lab-hint-shared-example = e.g. shared = ["helpers.lua"] (a submission then calls require("helpers"))
