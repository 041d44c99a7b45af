# plcsh messages (ru): tags. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).
tags-cannot-read = не удаётся прочитать файл тегов { $file }: { $reason }
tags-bad-encoding = { $problem }
tags-empty = в { $file } нет тегов
tags-duplicate = `{ $name }` определён повторно (как `{ $first }` в строке { $line }; регистр букв в именах не различается)
tags-name-empty = у тега пустое имя
tags-name-bad-start = `{ $name }` не может быть именем тега: начинается с `{ $char }` (имя начинается с буквы или `_`)
tags-name-bad-char = `{ $name }` не может быть именем тега: `{ $char }` не буква, не цифра и не `_`
tags-name-underscores = `{ $name }` не может быть именем тега: два `_` подряд или `_` в конце (идентификаторы IEC 61131-3)
tags-name-is-command = `{ $name }` — слово команды plcsh и не может быть именем тега
tags-name-is-keyword = `{ $name }` — ключевое слово IEC 61131-3 и не может быть именем тега
tags-name-is-operand = `{ $name }` читается как операнд { $family } и не может быть именем тега (добавьте слово: `{ $name }_val`)
tags-no-name = в строке есть адрес, но нет имени
tags-no-address = у `{ $name }` нет адреса
tags-bad-address = `{ $name }`: `{ $address }` — не адрес (в адресе нет пробелов и `/TYPE`: VW0, M0.3, %MW10; тип пишется в своём столбце)
tags-unknown-type = `{ $name }`: неизвестный тип `{ $dtype }` (BOOL, BYTE, SINT, WORD, INT, DWORD, DINT, REAL; также UINT, UDINT, USINT)
tags-type-does-not-fit = `{ $name }`: тип { $dtype } не подходит к { $address } ({ $bits ->
    [one] { $bits } бит
    [few] { $bits } бита
   *[many] { $bits } бит
})
tags-resolve-failed = `{ $name }`: { $address } здесь не операнд: { $problem }
tags-address-is-range = `{ $address }` — диапазон; адрес тега — один операнд
tags-overlap = `{ $name }` ({ $address }) перекрывается с `{ $other }` ({ $other_address }, строка { $line })
tags-csv-unclosed-quote = открытая здесь кавычка не закрыта (кавычка внутри поля в кавычках пишется дважды: "")
tags-csv-no-column = в строке заголовка нет столбца { $column } (слова заголовка: имя, адрес, тип, комментарий)
tags-toml-syntax = не TOML: { $detail }
tags-toml-no-table = в файле нет таблицы [tags]
tags-toml-entry = `{ $name }`: напишите адрес ("VW0") или таблицу ({ "{" } address = "VW0", type = "INT", comment = "…" { "}" })
tags-toml-unknown-key = `{ $name }`: неизвестный ключ `{ $key }` (address, type, comment)
tags-toml-not-text = `{ $name }`: `{ $key }` должен быть текстом в кавычках
tags-iec-expected = ожидалось { $expected }, найдено `{ $found }`
tags-iec-one-name = `{ $name }`: в объявлении с адресом одно имя (IEC 61131-3 §6.5.5)
tags-iec-no-address = у `{ $name }` нет адреса (напишите `{ $name } AT %MW10 : INT;`)
tags-iec-no-block = в файле нет блока VAR_GLOBAL … END_VAR
tags-iec-unclosed-block = VAR_GLOBAL без END_VAR
tags-iec-unclosed-comment = комментарий, открытый здесь с (*, не закрыт *)
tags-unknown-model = нет модели K2, FX или UMPK с именем `{ $model }` (plcsh models перечисляет модели K2)
tags-usage = укажите файл тегов: plcsh tags FILE, plcsh tags check FILE, plcsh tags export FILE --to csv|iec
tags-check-ok = { $file }: { $count ->
    [one] { $count } тег
    [few] { $count } тега
   *[many] { $count } тегов
}, проблем нет
tags-symbol-address = тег `{ $name }` имеет адрес { $address }, который здесь не операнд: { $problem }
tags-unknown-symbol = `{ $name }` — не тег и не операнд
tags-unknown-symbol-near = `{ $name }` — не тег (ближайшие: { $nearest })
tags-declared-address = { $file }:{ $line }:{ $column }: тег `{ $name }`: { $address } — не операнд этого ПЛК: { $problem }
tags-declared-twice = { $file }:{ $line }:{ $column }: тег `{ $name }` объявлен и в программе, и в { $tags } (строка { $tag_line })
tags-option-last = tags=FILE задаёт файл тегов и стоит последним: sim program load FILE.il tags=FILE.csv
tags-warning = предупреждение: { $warning }
tags-check-failed = { $file }: { $count ->
    [one] { $count } проблема
    [few] { $count } проблемы
   *[many] { $count } проблем
}
tags-bench-tags = стенд { $file }, теги для { $device }
