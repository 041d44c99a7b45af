# plcsh messages (en): data. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).

## Data sets (dataset, data save/diff/load)

data-usage = usage: data save FILE OPERAND… | data diff FILE [FILE2] | data load FILE
data-cannot-read = cannot read { $file }
data-bad-file = { $file } is not a data set file: { $reason }
data-no-identity = { $file } is not a data set file: its [device] table names no family or model
data-bad-operand = { $file } lists `{ $operand }`, which is no operand name: empty, with a space, or longer than 128 characters
data-bad-type = { $file } gives { $operand } the type `{ $dtype }`; the types are BOOL, BYTE, SINT, WORD, INT, DWORD, DINT and REAL
data-bad-value = { $file }: { $value } is not a { $dtype } value for { $operand }
data-duplicate = { $file } lists { $operand } twice
data-other-device = { $file } holds the data of a { $family } { $model } and { $device } is a { $dfamily } { $dmodel }: a data set loads only onto the family and model it was read from
data-families-differ = { $left } holds the data of a { $lfamily } and { $right } of a { $rfamily }: only sets of one family compare
data-unknown-operand = { $file } lists { $operand } as { $dtype }, which is not one operand of that type on { $device }: { $reason }
data-operand-elsewhere = { $operand } is on another device; a data set holds the operands of one device ({ $device })
data-no-area = `{ $area }` names an area of a K2 PLC and { $device } is not one: name its operands instead
data-retained-unknown = the retentive ranges of a real K2 are set in its hardware configuration (KincoBuilder), which cannot be read over Modbus: name them, e.g. data save FILE VB0..VB99 on { $device }
data-retained-none = { $device } retains no range: `sim retain VB0..VB99` sets the simulator's retentive ranges
data-saved = saved { $count ->
        [one] one operand
       *[other] { $count } operands
    } of { $device } to { $file }
data-same = no differences
data-loaded = wrote { $written ->
        [one] one operand
       *[other] { $written } operands
    }, each read back; { $unchanged } unchanged
data-read-back = { $operand } reads back { $back } after { $value } was written; the load stopped there after { $written ->
        [one] one write
       *[other] { $written } writes
    }
data-stopped = the load stopped at { $operand } after { $written ->
        [one] one write
       *[other] { $written } writes
    }: { $reason }
data-not-a-drive = { $device } is not a servo drive: servo params diff --with names another open drive
