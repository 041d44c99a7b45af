# plcsh messages (en): tags. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).
tags-cannot-read = cannot read the tag file { $file }: { $reason }
tags-bad-encoding = { $problem }
tags-empty = no tags in { $file }
tags-duplicate = `{ $name }` is defined again (as `{ $first }` at line { $line }; names do not differ by case)
tags-name-empty = a tag has an empty name
tags-name-bad-start = `{ $name }` is not a tag name: it starts with `{ $char }` (a name starts with a letter or `_`)
tags-name-bad-char = `{ $name }` is not a tag name: `{ $char }` is not a letter, a digit or `_`
tags-name-underscores = `{ $name }` is not a tag name: two `_` in a row, or `_` at the end (IEC 61131-3 identifiers)
tags-name-is-command = `{ $name }` is a command word of plcsh and cannot name a tag
tags-name-is-keyword = `{ $name }` is an IEC 61131-3 keyword and cannot name a tag
tags-name-is-operand = `{ $name }` reads as an operand of { $family } and cannot name a tag (add a word: `{ $name }_val`)
tags-no-name = a row has an address but no name
tags-no-address = `{ $name }` has no address
tags-bad-address = `{ $name }`: `{ $address }` is not an address (an address has no spaces and no `/TYPE`: VW0, M0.3, %MW10; the type goes in its own column)
tags-unknown-type = `{ $name }`: unknown type `{ $dtype }` (BOOL, BYTE, SINT, WORD, INT, DWORD, DINT, REAL; UINT, UDINT, USINT too)
tags-type-does-not-fit = `{ $name }`: type { $dtype } does not fit { $address } ({ $bits ->
    [one] { $bits } bit
   *[other] { $bits } bits
})
tags-resolve-failed = `{ $name }`: { $address } is not an operand here: { $problem }
tags-address-is-range = `{ $address }` is a range; a tag's address is one operand
tags-overlap = `{ $name }` ({ $address }) overlaps `{ $other }` ({ $other_address }, line { $line })
tags-csv-unclosed-quote = a quote opened here is not closed (a quote inside a quoted field is written twice: "")
tags-csv-no-column = the header row has no { $column } column (its words: name, address, type, comment)
tags-toml-syntax = not TOML: { $detail }
tags-toml-no-table = no [tags] table in the file
tags-toml-entry = `{ $name }`: write an address ("VW0") or a table ({ "{" } address = "VW0", type = "INT", comment = "…" { "}" })
tags-toml-unknown-key = `{ $name }`: unknown key `{ $key }` (address, type, comment)
tags-toml-not-text = `{ $name }`: `{ $key }` must be text in quotes
tags-iec-expected = expected { $expected }, found `{ $found }`
tags-iec-one-name = `{ $name }`: one name per declaration with an address (IEC 61131-3 §6.5.5)
tags-iec-no-address = `{ $name }` has no address (write `{ $name } AT %MW10 : INT;`)
tags-iec-no-block = no VAR_GLOBAL … END_VAR block in the file
tags-iec-unclosed-block = VAR_GLOBAL without END_VAR
tags-iec-unclosed-comment = a comment opened here with (* is not closed with *)
tags-unknown-model = no K2, FX or UMPK model is called `{ $model }` (plcsh models lists the K2 ones)
tags-usage = name a tag file: plcsh tags FILE, plcsh tags check FILE, plcsh tags export FILE --to csv|iec
tags-check-ok = { $file }: { $count ->
    [one] { $count } tag
   *[other] { $count } tags
}, no problems
tags-symbol-address = tag `{ $name }` is at { $address }, which is not an operand here: { $problem }
tags-unknown-symbol = `{ $name }` is neither a tag nor an operand
tags-unknown-symbol-near = `{ $name }` is not a tag (nearest: { $nearest })
tags-declared-address = { $file }:{ $line }:{ $column }: tag `{ $name }`: { $address } is not an operand of this PLC: { $problem }
tags-declared-twice = { $file }:{ $line }:{ $column }: tag `{ $name }` is declared in the program and in { $tags } (line { $tag_line })
tags-option-last = tags=FILE names the tag file and comes last: sim program load FILE.il tags=FILE.csv
tags-warning = warning: { $warning }
tags-check-failed = { $file }: { $count ->
    [one] { $count } problem
   *[other] { $count } problems
}
tags-bench-tags = bench { $file }, tags for { $device }
