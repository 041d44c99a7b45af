# plcsh messages (en): names. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).
names-duplicate = the name `{ $name }` is given twice (names are compared without case)
names-more-problems = … and { $count } more
names-not-attached = { $file }: { $count ->
        [one] one tag does not fit this device; no name was taken from the file
       *[other] { $count } tags do not fit this device; no name was taken from the file
    }
names-hint-check = fix the lines named above; `plcsh tags check { $file }` checks the file itself
names-not-one-operand = `{ $address }` is several operands; a tag names one
names-type-does-not-fit = the type { $dtype } does not fit `{ $address }` ({ $bits } bits)
names-hint-did-you-mean = did you mean { $names }?
