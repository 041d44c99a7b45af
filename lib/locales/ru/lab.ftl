# plcsh messages (ru): lab — лабораторные работы, сценарии и записи. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## Limits of a graded run (core::budget): the verdict names the limit passed.
budget-exceeded-minutes = превышен предел: { $n ->
    [one] { $n } минута
    [few] { $n } минуты
    [many] { $n } минут
   *[other] { $n } минуты
} времени симуляции
budget-exceeded-seconds = превышен предел: { $n ->
    [one] { $n } секунда
    [few] { $n } секунды
    [many] { $n } секунд
   *[other] { $n } секунды
} времени симуляции
budget-exceeded-instructions = превышен предел: { $count } инструкций Lua
budget-exceeded-memory = превышен предел памяти Lua: { $size }
budget-size-mib = { $n } МиБ
budget-size-bytes = { $n ->
    [one] { $n } байт
    [few] { $n } байта
   *[many] { $n } байт
}

## Verdicts of a graded submission (lab::grader, lab::runner).
lab-grader-error = ошибка программы оценки: { $error }
lab-runtime-error = ошибка выполнения: { $error }
lab-exceeded-write = превышен предел { $size } в каталоге для записи
lab-exceeded-wall = превышен страховочный предел реального времени { $seconds } с
lab-not-graded = не оценено: остановлено сигналом { $cause }
lab-refused-link = отклонено: { $file } — символическая ссылка; работа состоит из собственных файлов, а не ссылок (сдайте сам файл)
lab-refused-size = отклонено: размер работы { $n ->
    [one] { $n } байт
    [few] { $n } байта
   *[many] { $n } байт
}, больше предела работы { $cap } ([budget] submission в lab.toml)
lab-not-submission-kind = не сданная работа: нужен сценарий .lua или программа .il
lab-not-submission-missing = не сданная работа: нет такого файла
lab-not-accepted = не принято: эта лабораторная работа принимает решения { $kinds }
lab-plc-stopped = { $file }:{ $line }: ПЛК остановлен: { $error }
lab-plc-fault-code-at = { $place }: ПЛК остановлен по ошибке { $code } ({ $kind }): { $error } на `{ $at }`
lab-plc-fault-code = { $place }: ПЛК остановлен по ошибке { $code } ({ $kind }): { $error }
lab-plc-fault-at = { $place }: ПЛК остановлен ({ $kind }): { $error } на `{ $at }`
lab-plc-fault = { $place }: ПЛК остановлен ({ $kind }): { $error }
lab-device-replaced = { $file }: работа закрыла или заменила устройство лабораторной работы `{ $device }`
lab-cannot-read = не удаётся прочитать { $file }: { $error }
lab-cannot-start-lua = не удаётся запустить Lua: { $error }
lab-opening-devices = при открытии устройств лабораторной работы
lab-view = собственные файлы работы, общие модули и файлы-заготовки лабораторной работы и каталог для записи
lab-write-dir-role = каталог для записи
lab-cannot-create-write-dir = не удаётся создать каталог для записи для этого запуска
lab-write-dir-not-own = указанный каталог для записи не принадлежит программе оценки
lab-cannot-create-report-dir = не удаётся создать каталог для отчёта: { $error }
lab-cannot-create-write-dir-error = не удаётся создать каталог для записи: { $error }
lab-cannot-start-worker = не удаётся запустить рабочий процесс: { $error }
lab-worker-no-report = рабочий процесс завершился ({ $status }) без отчёта
lab-worker-error = рабочий процесс plcsh lab: { $error }
lab-worker-cannot-write = рабочий процесс plcsh lab: не удаётся записать { $file }: { $error }
lab-workers-running = рабочие процессы ещё выполняются
lab-no-executable = не удаётся найти исполняемый файл plcsh
lab-bytes-more = … ещё { $n ->
    [one] { $n } байт
    [few] { $n } байта
   *[many] { $n } байт
}

## `lab grade`, `lab new`, `lab check` (lab::runner, lab, cli::lab, shell::commands::lab).
lab-cannot-list = не удаётся прочитать список файлов { $dir }
lab-no-such-submission = { $file }: нет такого файла или каталога
lab-hint-submissions = укажите файлы сданных работ (.lua, .il) или каталоги с ними
lab-no-submissions = сданные работы не найдены (файлы .lua или .il)
lab-grade-stopped = lab grade остановлен сигналом { $cause } до того, как оценены все работы (оценено: { $done })
lab-hint-grade-again = запустите снова, чтобы оценить все работы
lab-cannot-write = не удаётся записать { $file }
lab-new-exists = { $dir } уже существует
lab-hint-new-name = укажите имя нового каталога: plcsh lab new NAME
lab-cannot-create = не удаётся создать { $dir }
lab-cannot-create-empty-dir = не удаётся создать каталог для пустой программы
lab-cannot-write-empty = не удаётся записать пустую программу
lab-not-in-sandbox = `lab` недоступна в запуске в песочнице (она запускает процессы и записывает каталоги)
lab-not-in-this-run = `lab` недоступна в этом запуске
lab-hint-check-table = таблица `plcsh lab check` показывает результат каждого критерия
lab-bad-jobs = jobs={ $jobs }: нужно число рабочих процессов ≥ 1
lab-needs-sub = `lab` требует new, check или grade с аргументами

## lab.toml (lab::config).
lab-cannot-read-file = не удаётся прочитать { $file }
lab-hint-lab-folder = лабораторная работа — это каталог с файлом lab.toml; `plcsh lab new NAME` записывает пример
lab-cannot-open = не удаётся открыть { $dir }
lab-no-such-file = { $file }: { $key } = "{ $name }": нет такого файла в { $dir }
lab-file-outside = { $file }: { $key } = "{ $name }" находится вне каталога лабораторной работы
lab-hint-files-inside = файлы лабораторной работы лежат в её каталоге, чтобы работу можно было скопировать целиком
lab-devices-one-way = { $file }: укажите устройства либо как bench = "FILE", либо таблицей [devices] (что-то одно)
lab-hint-devices-example = например, [devices] plc = "sim:K205-16DT"
lab-budget-not-time = { $file }: [budget] { $key } = "{ $text }" — не время, которое понимает plcsh
lab-budget-not-time-why = { $file }: [budget] { $key } = "{ $text }" — не время, которое понимает plcsh: { $error }
lab-hint-write-time = напишите "{ $time }" (единицы h, min, s, ms)
lab-hint-write-time-or = напишите "{ $time }" или "{ $seconds }" (единицы h, min, s, ms)
lab-hint-time-example = например, "10min", "90s", "1h" (единицы h, min, s, ms)
lab-budget-not-positive = { $file }: [budget] { $key } = "{ $text }" должно быть больше нуля
lab-budget-not-size = { $file }: [budget] { $key } = "{ $text }" — не размер
lab-hint-write-size = напишите "{ $size }" (единицы B, KiB, MiB, GiB)
lab-hint-size-example = например, "256MiB" (единицы B, KiB, MiB, GiB)
lab-budget-instructions-zero = { $file }: [budget] instructions должно быть больше нуля
lab-not-a-grant = { $file }: grants = ["{ $grant }"]: такое действие лабораторная работа не разрешает
lab-hint-did-you-mean-grant = может быть, "{ $near }"? grants: { $grants }
lab-hint-grants = grants: { $grants }
lab-points-negative = { $file }: [points] "{ $key }" = { $value }: баллы — число ≥ 0
lab-not-a-device = { $file }: device = "{ $device }" — не устройство лабораторной работы
lab-hint-did-you-mean-device = может быть, device = "{ $near }"? устройства лабораторной работы: { $devices }
lab-hint-devices = устройства лабораторной работы: { $devices }
lab-not-a-kind = { $file }: accepts = ["{ $kind }"]: не вид сданной работы
lab-hint-kinds = виды: { $kinds }
lab-shared-not-lua = { $file }: shared = ["{ $name }"]: общий модуль — это файл .lua
lab-hint-shared-example = например, shared = ["helpers.lua"] (работа затем вызывает require("helpers"))

## Lua scripts (script): errors plcsh raises in Lua code.
script-session-busy = сеанс занят: { $error }
script-no-session = нет сеанса: Lua выполняется только внутри plcsh
script-device-not-open = устройство `{ $device }` не открыто (закрыто или не открывалось)
script-no-output = нет вывода
script-bad-millis = { $what }: { $ms } — не длительность в миллисекундах (число ≥ 0)
script-json-too-deep = plcsh.json.encode: значение вложено глубже { $depth } таблиц (или содержит само себя)
script-hint-json-tree = JSON хранит деревья таблиц; сделайте значение более плоским
script-hint-json-split = массивы JSON — это списки 1…n без пропусков; у объектов строковые ключи — разделите таблицу
script-json-mixed = plcsh.json.encode: { $path } смешивает элементы списка и ключи
script-json-sparse = plcsh.json.encode: { $path } — список с пропусками (элементов: { $items }, наибольший индекс { $max })
script-unknown-option = { $what }: неизвестный параметр `{ $key }`
script-hint-did-you-mean-option = может быть, `{ $near }`? { $what } принимает { $options }
script-hint-options = { $what } принимает { $options }
script-wait-until-options = второй аргумент wait_until — {"{"}timeout=ms, every=ms{"}"} или тайм-аут, а не { $kind }
script-wait-until-timeout = wait_until: условие всё ещё ложно через { $time }
script-wait-until-timeout-what = wait_until: условие ({ $what }) всё ещё ложно через { $time }
script-hint-wait-until = увеличьте `timeout` или проверьте условие через plcsh.exec/get
script-method-error = { $method }: { $error }
script-hint-runs-command-line = { $method } выполняет командную строку, дополненную остальными аргументами
script-hint-runs-template = { $method } выполняет `{ $template }`, дополненную остальными аргументами
script-arg-not-utf8 = аргумент — не текст в UTF-8
script-cannot-pass = значение Lua типа { $kind } нельзя передать команде
script-option-not-utf8 = имя параметра — не UTF-8
script-option-not-string = имена параметров — строки, а не { $kind }
script-missing-argument = не хватает аргумента для `{ $spec }`
script-command-not-utf8 = текст команды — не UTF-8
script-nothing-to-run = нечего выполнять
script-sandbox-refused = { $what } недоступна в запуске в песочнице ({ $why ->
    [program] она запускает программу
    [delete] она удаляет файл
    [rename] она переименовывает файл
    [exit] она завершает plcsh
    [create] она создаёт файл
    [environment] она читает окружение машины
   *[library] она загружает библиотеку C
})
script-hint-sandbox = песочница разрешает симулированные устройства, вывод, проверки и файлы в каталогах лабораторной работы
script-lab-frame = (кадр стека лабораторной работы)
script-sandbox-terminal = { $function } без файла читает терминал: недоступно в запуске в песочнице
script-module-not-found = модуль '{ $name }' не найден: { $own ->
    [folder] в каталоге работы нет { $path }.lua
   *[single] у работы из одного файла нет собственных модулей
}; { $shared ->
    [none] лабораторная работа не предоставляет общих модулей
   *[some] лабораторная работа предоставляет { $modules }
}
script-require-not-string = неверный аргумент №1 функции 'require' (ожидалась строка, получено { $kind })
script-require-loop = модуль '{ $name }' требует сам себя (цикл вызовов require)
script-hint-require = работа подключает свои модули и общие модули лабораторной работы
script-date-field-missing = в таблице даты нет поля '{ $field }'
script-cannot-read = не удаётся прочитать { $file }: { $error }
script-os-exit = сценарий вызвал os.exit({ $code })
script-tmpname-cannot-create = os.tmpname: не удаётся создать файл в { $dir }: { $error }
script-tmpname-no-name = os.tmpname: нет свободного имени в { $dir }
script-no-built-in-module = модуля '{ $name }' нет среди встроенных в plcsh
script-sandbox-modules = (запуск в песочнице подключает только модули plcsh и самой лабораторной работы)
script-operand-not-text = имена операндов — текст
script-field-many-operands = `{ $text }` называет { $count ->
    [one] { $count } операнд
    [few] { $count } операнда
   *[many] { $count } операндов
}; поле — это один операнд
script-hint-read-range = диапазон читается так: { $device }:get("{ $text }")
script-hint-methods = методы: { $methods }; операнды — это поля: { $device }.VW0
script-hint-did-you-mean-method = может быть, { $count ->
    [1] { $a }
    [2] { $a } или { $b }
   *[3] { $a }, { $b } или { $c }
}?
script-no-method = у устройства `{ $device }` нет метода или операнда `{ $word }`
script-set-pairs-only = set: передавайте только пары {"{"}"OPERAND", value{"}"}
script-set-odd-arguments = set: { $count ->
    [one] { $count } аргумент
    [few] { $count } аргумента
   *[many] { $count } аргументов
}; передавайте OPERAND, value, OPERAND, value …
script-set-names-strings = set: имена операндов — строки
script-set-needs-values = set нужны операнды и значения
script-cannot-write-value = нельзя записать значение Lua типа { $kind } (используйте число, логическое значение или литерал, например "16#85")
script-method-dot = `{ $method }` — метод: вызывайте его через двоеточие, `dev:{ $method }(…)`, а не через точку `dev.{ $method }(…)`

## `plcsh publish` (cli::publish): readings to an MQTT broker.
publish-needs-broker = для publish нужен брокер
publish-hint-broker = --broker mqtt://HOST:1883 или url = "mqtt://HOST:1883" в разделе [mqtt] файла профилей
publish-password-without-user = пароль брокера без имени пользователя
publish-hint-username = задайте username в разделе [mqtt] файла профилей или PLCSH_MQTT_USERNAME
publish-cannot-read-ca = не удаётся прочитать [mqtt] ca_file { $file }: { $error }
publish-auth-refused = брокер { $broker } отклонил учётные данные ({ $why })
publish-hint-auth = проверьте username в разделе [mqtt] файла профилей (или PLCSH_MQTT_USERNAME) и PLCSH_MQTT_PASSWORD, а также что ACL брокера разрешает этому пользователю подключаться
publish-tls-failed = TLS с брокером { $broker } не удался ({ $why })
publish-hint-tls = сертификат брокера должен проверяться по ca_file в разделе [mqtt] (его CA, PEM) или по корневым сертификатам системы и называть узел из --broker
publish-no-broker = ни один брокер MQTT не ответил по адресу { $broker } за { $seconds } с от запуска ({ $why })
publish-hint-no-broker = запущен ли брокер и верны ли узел и порт в --broker (mqtt:// 1883, mqtts:// 8883)?
publish-not-an-operand = `{ $operand }` — не операнд этого устройства: { $error }
publish-hint-fix-operand = ничего не опубликовано; исправьте операнд (plcsh -c 'get OPERAND' показывает, что отвечает устройство)
publish-not-an-operand-fleet = `{ $operand }` — не операнд ни одного устройства группы `{ $fleet }`: { $error }
publish-not-an-operand-members = `{ $operand }` — не операнд устройств { $members }{ $more ->
    [0] {""}
   *[other] {" "}и ещё { $more }
}: { $error }
publish-hint-fix-operand-fleet = ничего не опубликовано; исправьте операнд (plcsh -f FLEET -c 'get OPERAND' показывает, что отвечает каждое устройство)
publish-bad-every = --every { $every } — не длительность
publish-hint-every = например, 1s, 250ms
publish-no-mqtt-thread = не удаётся запустить поток MQTT
publish-no-poll-threads = не удаётся запустить потоки опроса
publish-connected = подключено к { $broker }
publish-broker-away = брокер { $broker } недоступен ({ $why }); показания хранятся в пределах --buffer и отправляются, когда он вернётся
publish-device-back = { $device } снова отвечает
publish-polling-stopped = опрос остановлен; доставляется то, что в очереди (у брокера есть несколько секунд, чтобы принять)
publish-summary = опубликовано сообщений: { $published } в { $broker } (группа { $group }{ $shard ->
    [some] , часть { $shard_of }
   *[none] {""}
}); отброшено, пока брокер был недоступен: { $away }; отброшено: { $behind } и пропущено опросов: { $skipped }, потому что plcsh не успевал; отброшено при остановке (не доставлено): { $undelivered }; переподключений: { $reconnects }{ $worst ->
    [some] ; больше всего отстали: { $worst_list }
   *[none] {""}
}{ $offline ->
    [some] ; не в сети: { $offline_list }
   *[none] {""}
}

## `plot` pictures (plot) and fleet runs (fleet).
plot-cannot-draw = не удаётся нарисовать график: { $error }
plot-bad-picture = to={ $path }: рисунки бывают .png или .svg
plot-hint-picture = например, to=ramp.png или to=ramp.svg
plot-cannot-write = не удаётся записать { $path }: { $error }
plot-bad-size = size={ $text } — не ШИРИНАxВЫСОТА (например, 900x400)
plot-size-range = size={ $text }: каждая сторона — от { $min } до { $max } пикселей
fleet-internal-error = работа с этим устройством остановилась из-за внутренней ошибки
fleet-no-thread = не удаётся запустить рабочий поток
fleet-timeout = нет результата за { $seconds } с
fleet-hint-timeout = устройство может быть выключено или медленно отвечать; увеличьте --device-timeout или проверьте его линию связи отдельно
fleet-not-started = не запущено: выполнение для группы устройств остановлено
fleet-all-ok = группа { $fleet }: { $count ->
    [one] { $count } устройство
    [few] { $count } устройства
   *[many] { $count } устройств
}, все в порядке ({ $ms } мс, { $jobs } одновременно)
fleet-failed = группа { $fleet }: ошибка на { $failed } из { $count ->
    [one] { $count } устройства
   *[other] { $count } устройств
}: { $devices } ({ $ms } мс, { $jobs } одновременно)

## Recordings (record): --record, `replay`.
record-cannot-read = не удаётся прочитать запись { $file }
record-hint-give-file = укажите файл, записанный с --record FILE
record-not-readable = { $file } — не читаемая запись pcapng: { $error }
record-hint-capture = укажите файл, записанный plcsh --record FILE, или захват pcapng/pcap трафика Modbus TCP на интерфейсе Ethernet или loopback (tshark -i lo -f 'tcp port 502' -w FILE.pcapng)
record-snap-length = { $count ->
    [one] { $count } пакет обрезан
    [few] { $count } пакета обрезаны
   *[many] { $count } пакетов обрезаны
} по длине захвата (snap length): кадры в них неполные (захватите снова без -s или с -s 0)
record-no-tcp = { $count ->
    [one] его { $count } пакет не несёт
   *[other] его пакеты ({ $count }) не несут
} данных TCP (трафик Modbus TCP не захвачен)
record-bytes-missing = { $lost ->
    [one] { $lost } байт
    [few] { $lost } байта
   *[many] { $lost } байт
} от { $from } к { $to } отсутствуют в захвате (кадры рядом с ними могут показываться как искажённые)
record-cannot-create = не удаётся создать запись { $file }
record-hint-writable = проверьте, что каталог существует и доступен для записи
record-cannot-write = не удаётся записать запись { $file }
record-incomplete = запись { $file } неполная: { $error }
replay-no-sim-plc = { $link }: на стенде нет симулированного ПЛК
replay-no-sim-drive = { $link }: на стенде нет симулированного сервопривода
replay-other-protocol = { $link }: кадры { $protocol } (воспроизведение охватывает линии Modbus и сервоприводов)
replay-undeclared-protocol = { $link }: кадры необъявленного протокола
replay-helper-cannot-run = { $link }: вспомогательная программа не может работать: { $error }
replay-no-reply-recorded = ответ не записан; симулятор отвечает
replay-no-reply-replayed = ответ записан; симулятор не отвечает
replay-no-requests = в { $file } нет записанных запросов
replay-hint-record = запишите сеанс, в котором идёт обмен с устройством по Modbus или по линии сервопривода: plcsh --record FILE --device plc=tcp://…
publish-command-too-big = команда — не больше { $max } байт
publish-command-not-json = не JSON: { $error }
publish-command-not-object = команда — это объект JSON {"{"}"operand":…, "value":…{"}"}
publish-command-no-operand = нет `operand` (строки)
publish-command-no-value = нет `value` (числа, true/false или литерала, например "16#85")
publish-command-one-write = одна команда — один операнд и одно значение
publish-write-no-allow-list = запись отклонена: у `{ $device }` нет списка разрешённых операндов: записи от брокера требуют его в профиле
publish-write-profile-no-allow-list = запись отклонена: в профиле `{ $device }` нет списка разрешённых операндов: записи от брокера требуют его
publish-no-such-member = `{ $device }` — не устройство группы `{ $group }` (устройства: { $members })
publish-no-such-member-near = `{ $device }` — не устройство группы `{ $group }` (устройства: { $members }); может быть, { $near }?
publish-no-runtime = не удаётся запустить среду выполнения: { $error }

## Capture files (record::container): pcapng and pcap, as read for `replay` and `decode`.
capture-empty = файл пуст (0 байт)
capture-bad-start = файл начинается с { $bytes }, а не с заголовка секции pcapng (0A 0D 0D 0A) или заголовка файла pcap
capture-damaged-block = байты { $from }…{ $to } ({ $count } байт) повреждены ({ $why }); чтение продолжается с блока по смещению { $next }
capture-no-block = в файле нет ни одного целого блока ({ $size } байт): { $what ->
    [header] заголовок секции
   *[block] блок
} по смещению { $at } { $state ->
    [cut] обрезан
   *[damaged] повреждён
} ({ $why })
capture-block-truncated = блок по смещению { $at } { $state ->
    [cut] обрезан
   *[damaged] повреждён
}: { $why }
capture-bad-magic = его признак порядка байтов { $magic } — ни 4D 3C 2B 1A, ни 1A 2B 3C 4D
capture-short-section = осталось { $left } байт, меньше первых 12 байт заголовка секции
capture-short-block = осталось { $left } байт, меньше заголовка блока
capture-unknown-block = неизвестный тип блока { $kind }
capture-bad-block-length = длина блока { $total } не кратна 4 или меньше 12
capture-block-past-end = длина блока { $total }, а осталось { $left } байт
capture-lengths-differ = его длина в конце не совпадает с длиной в начале
capture-block-short = { $block ->
    [section] заголовок секции
    [interface] описание интерфейса
    [enhanced] расширенный блок пакета
    [packet] блок пакета
   *[simple] простой блок пакета
} короче { $bytes } байт
capture-packet-past-block = длина пакета { $length } выходит за пределы его блока
capture-no-interface = пакет ссылается на интерфейс { $id }, который не объявлен ни одним описанием интерфейса
capture-short-pcap = { $size } байт: короче заголовка файла pcap (24)
capture-short-record = осталось { $left } байт, меньше заголовка записи
capture-record-past-end = длина записи { $length }, а осталось { $left } байт
capture-record-impossible = длины записи { $length }/{ $original } или доля секунды невозможны
capture-record-unreadable = нечитаемый заголовок записи
capture-damaged-record = байты { $from }…{ $to } ({ $count } байт) повреждены ({ $why }); чтение продолжается с записи по смещению { $next }
capture-record-truncated = запись по смещению { $at } обрезана или повреждена ({ $why })
