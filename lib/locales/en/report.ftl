# plcsh messages (en): report. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).

## Commissioning reports (src/report): headings and labels of the HTML report.
report-site = Site
report-operator = Operator
report-date = Date
report-time = Time
report-clock-stepped = simulated (stepped) time, { $start } to { $end }
report-clock-real = machine time, { $start } to { $end }
report-version = Made with
report-result-passed = PASSED
report-result-failed = FAILED
report-summary = { $ok } of { $total } steps done, { $failed } failed, { $skipped } skipped
report-devices = Devices
report-no-devices = No device was open.
report-device-family = Family
report-device-model = Model
report-device-link = Address
report-device-kind = Kind
report-device-simulated = simulator
report-device-real = real device
report-checklist = Checklist
report-no-steps = No checklist was run.
report-step = Step
report-result = Result
report-duration = Duration
report-note = Note
report-step-ok = done
report-step-failed = FAILED
report-step-failed-optional = failed (optional)
report-step-skipped = skipped
report-expected = Expected
report-measured = Measured
report-values = Values measured
report-results = { $count ->
    [one] { $count } command result recorded (in the JSON twin)
   *[other] { $count } command results recorded (in the JSON twin)
}
report-params = Parameter sets
report-no-params = No parameter set was saved, loaded or compared.
report-params-saved = { $device }: saved to { $file }
report-params-loaded = { $device }: loaded from { $file }
report-params-compared = { $device }: compared
report-params-reference = Reference: { $file }
report-params-same = No parameter differs from the reference.
report-parameter = Parameter
report-object = Object
report-reference = Reference
report-drive = Drive
report-curves = Curves
report-no-curves = No curve was recorded.
report-trace-caption = { $samples } samples over { $span }.
report-trace-decimated = Drawn and kept as the minimum and maximum of each of { $columns } columns.
report-trace-step = Recorded in step { $step }.
report-curve-figures = { $name }: min { $min }, max { $max }, last { $last }
report-writes = Writes to devices
report-writes-none = plcsh wrote nothing to a device during the run.
report-writes-not-kept = { $count } more writes were made and only counted.
report-device = Device
report-operand = Operand or object
report-old = Old value
report-new = New value
report-refused = refused: { $reason }
report-notes = Notes
report-no-notes = No notes.
report-footer = Made by plcsh { $version }. Curves keep at most two points per pixel column ({ $columns } columns); the write log keeps the first { $writes } writes.
report-cannot-write = cannot write the report { $file }: { $reason }
report-bad-record = the commissioning record cannot be read: { $reason }
