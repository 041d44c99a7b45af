# plcsh messages (ru): names. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).
names-duplicate = имя `{ $name }` задано дважды (имена сравниваются без учёта регистра)
names-more-problems = … и ещё { $count }
names-not-attached = { $file }: { $count ->
        [one] { $count } тег не подходит к этому устройству; ни одно имя из файла не принято
        [few] { $count } тега не подходят к этому устройству; ни одно имя из файла не принято
       *[many] { $count } тегов не подходят к этому устройству; ни одно имя из файла не принято
    }
names-hint-check = исправьте названные строки; `plcsh tags check { $file }` проверяет сам файл
names-not-one-operand = `{ $address }` — несколько операндов; тег называет один
names-type-does-not-fit = тип { $dtype } не подходит к `{ $address }` ({ $bits } бит)
names-hint-did-you-mean = может быть, { $names }?
