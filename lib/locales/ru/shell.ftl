# plcsh messages (ru): shell — команды и параметры оболочки и командной строки. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## Ошибки самой командной строки (cli::clap_error): что нашёл clap, в его раскладке

cli-error = ошибка: { $message }
cli-error-unknown-argument = неизвестный аргумент '{ $arg }'
cli-error-unknown-subcommand = неизвестная подкоманда '{ $subcommand }'
cli-error-invalid-value = недопустимое значение '{ $value }' для '{ $arg }'
cli-error-value-missing = для '{ $arg }' нужно значение, но оно не задано
cli-error-possible-values = [допустимые значения: { $values }]
cli-error-value-refused = недопустимое значение '{ $value }' для '{ $arg }': { $reason }
cli-error-no-equals = значение для '{ $arg }' задаётся через знак равенства
cli-error-too-many-values = лишнее значение '{ $value }' для '{ $arg }': больше значений не ожидалось
cli-error-too-few-values = '{ $arg }' требует не менее { $min } { $min ->
    [one] значения
   *[other] значений
}, а задано только { $given }
cli-error-wrong-number-of-values = '{ $arg }' требует { $expected } { $expected ->
    [one] значение
    [few] значения
   *[many] значений
}, а задано { $given }
cli-error-missing-arguments = { $count ->
    [one] не задан обязательный аргумент:
   *[other] не заданы обязательные аргументы:
}
cli-error-missing-subcommand = '{ $command }' требует подкоманду, но она не указана
cli-error-subcommands = [подкоманды: { $values }]
cli-error-used-twice = аргумент '{ $arg }' нельзя указывать несколько раз
cli-error-conflict = аргумент '{ $arg }' нельзя использовать вместе с { $other }
cli-error-conflict-others = аргумент '{ $arg }' нельзя использовать вместе с одним или несколькими другими указанными аргументами
cli-error-invalid-utf8 = в одном или нескольких аргументах недопустимые байты UTF-8
cli-error-similar-subcommand = совет: { $count ->
    [one] есть похожая подкоманда
   *[other] есть похожие подкоманды
}: { $names }
cli-error-similar-argument = совет: { $count ->
    [one] есть похожий аргумент
   *[other] есть похожие аргументы
}: { $names }
cli-error-similar-value = совет: { $count ->
    [one] есть похожее значение
   *[other] есть похожие значения
}: { $names }
cli-error-pass-as-value = совет: чтобы передать '{ $arg }' как значение, пишите '{ $example }'
cli-error-remove-dashes = совет: подкоманда '{ $subcommand }' есть; чтобы её вызвать, уберите '--' перед ней
cli-error-tip = совет: { $tip }
cli-error-more = Подробнее: '{ $help }'.
cli-no-such-subcommand = plcsh: у `{ $command }` нет подкоманды `{ $subcommand }`; её подкоманды: { $subcommands }
cli-help-describes-each = `{ $command } --help` описывает каждую

## Подкоманды и параметры подкоманд (`plcsh sim serve --help`; cli::localise)

cli-default = [по умолчанию: { $value }]
cli-possible-values = [допустимые значения: { $values }]
cli-help-subcommand = Показать эту справку или справку по указанным подкомандам
cli-models-name = Одна модель (достаточно однозначного начала: K209EA)
cli-completions-shell = Оболочка, для которой вывести скрипт
cli-completions-write = Записать все скрипты в DIR (plcsh.bash, _plcsh, plcsh.fish, _plcsh.ps1)
cli-sim-serve = Предоставить симулятор по Modbus TCP, по Modbus RTU на псевдотерминале и/или по RTU поверх TCP
cli-sim-serve-tcp = Modbus TCP на ADDR (`127.0.0.1:5020`, `5020`, `0` — свободный порт; только локальный адрес, если не указан хост)
cli-sim-serve-rtu-pty = Modbus RTU на новом псевдотерминале, с символической ссылкой на его устройство в LINK
cli-sim-serve-rtu-tcp = Кадры Modbus RTU поверх TCP на ADDR (как их передаёт шлюз RS-485/Ethernet)
cli-sim-serve-unit = Адрес ведомого устройства (unit id), на который отвечает K2; запросы к другим адресам остаются без ответа
cli-sim-serve-agent = Выполнять программу-помощник в ПЛК (lib/k2_agent.il) с почтовым ящиком по этому адресу V
cli-sim-serve-program = Выполнять эту программу IL в предоставляемом K2 (docs/il.md); ошибки загрузки останавливают сервер
cli-sim-serve-servo-pty = Предоставить симулируемые сервоприводы Kinco на новом псевдотерминале; LINK становится символической ссылкой на него
cli-sim-serve-servo-tcp = Предоставить симулируемые сервоприводы Kinco на TCP-порту, как это делает сервер последовательных устройств (kinco+tcp://ADDR)
cli-sim-serve-servo-control = Канал управления линией сервоприводов в PATH (по умолчанию LINK.ctl рядом со ссылкой --servo-pty); клиенты указывают его как `control=PATH` (например, `kinco+tcp://ADDR?control=PATH`)
cli-sim-serve-servo-id = Адреса сервоприводов на линии (несколько приводов на одной линии)
cli-sim-serve-servo-loop = Петлевой режим RS232: повторять каждый запрос перед ответом (подключаться с echo=1)
cli-sim-serve-servo-baud = Время на линии: ответ занимает время передачи кадра на этой скорости передачи данных (10 бит на байт)
cli-sim-serve-servo-latency = Время на линии: задержка привода перед ответом (например, 1ms, 0)
cli-sim-serve-servo-instant = Отвечать сразу, а не со скоростью линии (измерения производительности, CI)
cli-sim-serve-servo-strict = Отказывать в записи, код размера которой не совпадает с размером объекта (код отказа 0x06070010)
cli-sim-serve-fx-pty = Предоставить порт программирования симулируемого ПЛК FX на новом псевдотерминале (символическая ссылка в LINK)
cli-sim-serve-fx-tcp = Предоставить порт программирования симулируемого ПЛК FX на TCP-порту (fx+tcp://ADDR)
cli-sim-serve-fx-link-pty = Предоставить компьютерную связь того же ПЛК FX (формат 1, с контрольной суммой) на другом псевдотерминале
cli-sim-serve-fx-link-tcp = Предоставить компьютерную связь того же ПЛК FX на TCP-порту (fxlink+tcp://ADDR)
cli-sim-serve-fx-model = Модель симулируемого ПЛК FX (FX1S, FX1N, FX2N, FX3U; FX2NC и FX3UC означают FX2N и FX3U)
cli-sim-serve-fx-station = Номер станции компьютерной связи (0–31)
cli-sim-serve-fx-program = Список инструкций FX, который выполняет симулируемый ПЛК FX (docs/il.md, «The FX family»)
cli-sim-serve-umpk-pty = Предоставить симулируемый учебный ПЛК УМПК на новом псевдотерминале; LINK становится символической ссылкой на него
cli-sim-serve-umpk-tcp = Предоставить симулируемый учебный ПЛК УМПК на TCP-порту (umpk+tcp://ADDR)
cli-sim-serve-umpk-model = Модель симулируемого УМПК (UMPK8 или UMPK16)
cli-sim-serve-umpk-status-bits = Номера битов W,H,R,E,P,T в слове состояния УМПК
cli-sim-serve-umpk-flash-fail = Сделать так, чтобы запись flash-памяти симулируемого УМПК не удавалась на этой странице в 64 байта (программирование получает `W`): 0–31 у УМПК8, 0–47 у УМПК16
cli-sim-serve-umpk-state = Где симулируемый УМПК хранит flash-память, сведения о программе и историю ошибок (по умолчанию — по файлу на модель и линию в каталоге данных пользователя; `none` ничего не хранит)
cli-sim-serve-umpk-program = Программа лабораторной работы на IL, которую симулируемый УМПК выполняет каждый цикл ПЛК 10 мс (docs/il.md, «The UMPK family»)
cli-sim-serve-fx-control = Канал управления предоставляемым ПЛК FX в PATH (по умолчанию LINK.ctl рядом со ссылкой --fx-pty): переключение входов X, молчащая линия, залипшие входы, пока клиенты работают с его портами
cli-sim-serve-umpk-control = Канал управления предоставляемым УМПК в PATH (по умолчанию LINK.ctl рядом со ссылкой --umpk-pty): входы, меандр и неисправности, пока программа лабораторной работы работает с линией
cli-sim-serve-k2-control = Канал управления предоставляемым K2 в PATH (по умолчанию LINK.ctl рядом со ссылкой --rtu-pty): добавление, просмотр и сброс неисправностей и чтение журнала событий неисправностей, пока клиенты опрашивают ПЛК (`plcsh sim control PATH …` или `control=PATH` в URL клиента)
cli-sim-serve-fault = Внести неисправность в предоставляемый K2, например `--fault "no-reply on VW100 after=2s times=1"` (можно повторять; см. `help sim`)
cli-sim-serve-max-connections = Сколько сетевых соединений обслуживается одновременно (на каждый транспорт); лишние закрываются сразу после приёма
cli-sim-serve-idle-timeout = Закрывать сетевое соединение, по которому ничего не приходит столько времени (`300s`, `2m`, `500ms`)
cli-sim-serve-strict-unit = По Modbus TCP отвечать только на адрес --unit (по умолчанию адрес 0xFF — тоже это устройство, как в libmodbus)
cli-sim-serve-fleet = Предоставить N симулируемых K2, каждый со своей памятью, на N TCP-портах (с --tcp: порт 0 даёт каждому свободный порт, порт P даёт P, P+1, …); строка готовности перечисляет их в `fleet` (docs/fleets.md)
cli-sim-serve-rfc2217 = TCP-порты последовательных параметров (--rtu-tcp, --servo-tcp, --fx-tcp, --fx-link-tcp, --umpk-tcp) работают по RFC 2217 (Telnet COM-PORT-OPTION), а не как простой TCP: для FAMILY+rfc2217:// и драйверов виртуальных COM-портов
cli-sim-control = Отправить одну строку в канал управления предоставляемого симулятора (неисправности, события) и вывести ответ
cli-sim-control-path = Канал управления (`k2_control`, `umpk_control` или `servo_control` из строки готовности сервера)
cli-sim-control-words = Строка управления, например `fault no-reply times=2`, `faults`, `events`, `fault clear`
cli-agent-il = Вывести программу-помощник (список инструкций K2) для KincoBuilder
cli-agent-il-model = Модель ПЛК: программа-помощник выполняет только те импульсные выходы, счетчики и режимы счетчиков, которые есть у этой модели (по умолчанию — модель симулятора по умолчанию)
cli-agent-il-base = Начало почтового ящика: чётный адрес байта V ниже области E2PROM (VB3648)
cli-agent-check = Самопроверка программы-помощника в ПЛК: подпись, версия, частота сканирования, системные биты, часы и отказ PLS; записывает только почтовый ящик и возвращает использованные байты SM (docs/agent.md)
cli-agent-check-url = ПЛК: tcp://HOST:PORT?agent=VB3400, rtu:PORT?… или имя профиля (agent=VB3400, если в URL его нет)
cli-probe-url = ПЛК: tcp://HOST:PORT, rtu:PORT?baud=…, rtu+tcp://HOST:PORT или имя профиля
cli-probe-report = Также записать результаты отчётом Markdown в FILE
cli-probe-reads = Сколько чтений замерять для времени ответа (p50, p99)
cli-probe-scan-serial = Если последовательная линия не отвечает, перебрать обычные параметры связи (9600…115200 бит/с, без четности, четный или нечетный контроль) и сказать, на какие пришёл ответ
cli-run-sandbox = Выполнить чужой скрипт: без os.execute, io.popen, os.remove/rename/exit, библиотек C и библиотеки debug; файлы записываются только в --write-dir
cli-run-write-dir = С --sandbox: каталог, в котором скрипт может записывать файлы (без него — нигде)
cli-run-fleet = Выполнить скрипт на всех устройствах этой группы одновременно, каждый в своём состоянии Lua (docs/fleets.md)
cli-run-report = Записать отчёт о пусконаладке: этот файл HTML и рядом его JSON-двойник (docs/commissioning.md). Программа пусконаладки записывает туда свой контрольный список; любой другой скрипт получает устройства и журнал каждой сделанной им записи
cli-run-script = Скрипт Lua
cli-run-args = Аргументы для скрипта (`arg[1]`… и `...`): всё после скрипта, даже слова, похожие на флаги plcsh. Флаги для plcsh пишутся до скрипта
cli-record-show = Вывести запись как расшифрованную временную шкалу (имена операндов K2, имена объектов сервопривода); с --json — по объекту на кадр
cli-record-file = Файл, записанный с --record
cli-replay-sim-model = Симулировать эту модель K2 вместо той, что названа в каждой записанной линии связи
cli-replay-snapshot = Запустить симулируемый K2 из этого снимка (файл или имя, сохранённое через `sim snapshot save`)
cli-replay-agent = Выполнять программу-помощник (lib/k2_agent.il) с почтовым ящиком по этому адресу V. Без этого параметра программа-помощник запускается, если в записи видно чтение её блока состояния
cli-publish-broker = Брокер: mqtt://HOST:PORT или mqtts://HOST:PORT для TLS (по умолчанию `url` в разделе [mqtt] файла профилей)
cli-publish-fleet = Публиковать все устройства этой группы (по умолчанию — текущее устройство)
cli-publish-every = Как часто опрашивать каждое устройство
cli-publish-qos = Качество обслуживания MQTT для значений: 0 (не более одного раза) или 1 (не менее одного раза)
cli-publish-on-change = Публиковать значение только при изменении (больше чем на --deadband); иначе — при каждом опросе
cli-publish-deadband = С --on-change: наименьшее публикуемое изменение (в единицах операнда)
cli-publish-buffer = Наибольшее число показаний в очереди к брокеру: пока его нет, самые старые сверх этого отбрасываются; пока он подключён, но plcsh не успевает, новое значение темы заменяет стоящее в очереди (оба случая подсчитываются)
cli-publish-mqtt-version = Версия протокола MQTT
cli-publish-count = Остановиться после стольких опросов каждого устройства (по умолчанию — до Ctrl-C)
cli-publish-client-id = Идентификатор клиента MQTT (по умолчанию plcsh-GROUP-PID)
cli-publish-accept-writes = Принимать от брокера записи на plcsh/GROUP/DEVICE/set, только в операнды из списка разрешённых в профиле устройства (ответы на plcsh/GROUP/DEVICE/reply); профили только для чтения записи не принимают
cli-publish-shard = Публиковать только эту часть группы (K из N публикующих; по умолчанию `shard` в разделе [mqtt] файла профилей)
cli-publish-operands = Публикуемые операнды (можно диапазоны: VW100..VW110)
cli-tags-file = Файл тегов для просмотра (CSV, TOML `[tags]` или объявления IEC `VAR_GLOBAL`)
cli-tags-model = Модель, к операндам которой относятся адреса (K2, FX или УМПК; по умолчанию — модель симулируемого K2)
cli-tags-format = Читать файл в этом формате, а не определять формат по имени и тексту
cli-tags-check = Проверить файл тегов: по строке на каждую ошибку с file:line:column; код завершения 1, если есть хоть одна
cli-tags-export = Записать файл тегов в другой форме (CSV или IEC VAR_GLOBAL) на стандартный вывод или в --output
cli-tags-export-to = Форма для записи
cli-tags-export-output = Записать сюда, а не на стандартный вывод (файл заменяется целиком, атомарно)

## Строки хода работы и заметки в стандартном потоке ошибок (shell, cli, signals)

shell-requests-on-wire = { $command }: { $count } { $count ->
    [one] запрос
    [few] запроса
   *[many] запросов
} по линии связи
shell-samples = { $count } { $count ->
    [one] выборка
    [few] выборки
   *[many] выборок
}
shell-sample-report = { $command }: { $samples } { $samples ->
    [one] выборка
    [few] выборки
   *[many] выборок
} за { $clock } с по часам сессии ({ $clock_rate } Гц; запрошено { $asked_rate } Гц), { $wall } с реального времени ({ $wall_rate } Гц), { $requests } { $requests ->
    [one] запрос
    [few] запроса
   *[many] запросов
}{ $interrupted ->
    [yes] , прервано
   *[no] { "" }
}
shell-umpk-programming = программирование { $bar } запись { $record }/{ $records }
shell-not-connected-yet = plcsh: { $device }: { $reason } — нет связи; следующая команда попробует снова
shell-state-taken = plcsh: предупреждение: { $reason }: plc этой оболочки начинает с чистого состояния и ничего не сохраняет (как с --state none); чтобы хранить своё состояние, запустите её с --state FILE
shell-stop-overdue = plcsh: остановлено: остановка не завершилась за { $seconds } с (обработчики прерывания ещё работают?)

## Ошибки использования в строках оболочки (shell::lex, shell::commands::forms)

shell-hint-close-quote = закройте кавычку; внутри двойных кавычек пишите \" для кавычки и \\ для обратной косой черты, или используйте одинарные кавычки
shell-hint-one-file = только один файл: { $line }
shell-hint-quote-path = путь с пробелами пишется в кавычках: { $line }
shell-one-file-only = { $form } принимает один файл, а не { $count } { $count ->
    [one] слово
    [few] слова
   *[many] слов
} (`{ $words }`)
shell-cli-only-run = `run` — команда командной строки: plcsh run SCRIPT.lua [ARGS…]; в оболочке — lua dofile("SCRIPT.lua")
shell-cli-only-replay = `replay` — команда командной строки: plcsh replay FILE.pcapng (она сама создаёт свои симуляторы)
shell-cli-only-record = `record` — команда командной строки: plcsh record show FILE.pcapng; чтобы записать этот сеанс, запустите plcsh с --record FILE
shell-cli-only-completions = `completions` — команда командной строки: plcsh completions bash|zsh|fish|powershell
shell-cli-only-serve = предоставление симуляторов — команда командной строки: plcsh sim serve --tcp 5020 …
shell-no-options = `{ $forms }` не принимает параметров (указано `{ $key }=`)
shell-hint-the-form = форма команды: { $forms }; `help { $command }` показывает все формы
shell-hint-nothing-after-files = после { $files ->
    [one] файла
   *[other] файлов
} ничего не пишется; `{ $help }` показывает все формы
shell-hint-quote-name = путь или имя с пробелами пишется в кавычках: { $line }
shell-unexpected-after = лишнее `{ $extra }` после `{ $typed }`: форма команды — { $forms }
shell-hint-number-and-unit = число и единица измерения пишутся одним словом: { $line }
shell-no-arguments = лишнее `{ $extra }`: `{ $command }` не принимает аргументов
shell-hint-nothing-after = после этого ничего не пишется; `{ $help }` показывает все формы

## Операнды, параметры и устройства команды (shell::commands::io, shell::sample, session, guard)

shell-needs-operand = { $command } требует хотя бы один операнд
shell-set-needs-items = set требует элементы OPERAND=VALUE
shell-set-not-item = `{ $item }` — не OPERAND=VALUE
shell-set-st-assignment = `:=` — присваивание языка ST; в plcsh пишется `{ $operand }={ $value }`
shell-set-commas = записи разделяются запятыми: `set { $line }`
shell-option-positive = { $key } должно быть больше нуля
shell-name-an-operand = укажите хотя бы один операнд
shell-count-not-number = count={ $value } — не число
shell-count-at-least-one = count должно быть не меньше 1
shell-unknown-option = неизвестный параметр `{ $key }`
shell-hint-options = параметры: { $options }; { $usage }
shell-not-traced = `{ $name }` нет в последней записи trace
shell-hint-traced = записаны: { $names }
session-bad-device-name = `{ $name }` — не имя устройства: только латинские буквы A-Z a-z, цифры, _ и -
session-hint-device-name = например, connect press1 sim:K209EA-50DX (имя пишется перед операндами: press1:VW0)
session-sandbox-real-profile = `{ $url }` — профиль настоящего устройства: запуск в песочнице открывает только симулируемые устройства
session-sandbox-not-url = `{ $url }` — не URL устройства: запуск в песочнице открывает симулируемые устройства только по URL
session-from-profile = из профиля `{ $profile }` ({ $origin })
session-no-device-named = нет устройства с именем `{ $name }`
session-hint-none-open = ни одно устройство не открыто; добавьте устройство через --device NAME=URL
session-hint-open-devices = открытые устройства: { $names }
session-none-open = ни одно устройство не открыто
session-hint-add-device = добавьте устройство через --device NAME=URL или `connect NAME URL`
guard-read-only-action = { $action } запрещено (изменяет { $name }): сеанс только для чтения (--read-only)
guard-read-only-write = запись запрещена: сеанс только для чтения (--read-only)
guard-hint-read-only = чтение работает; чтобы записывать, запустите plcsh без --read-only
cli-config-missing = --config { $file }: нет такого файла
cli-hint-config-missing = укажите существующий devices.toml или уберите --config, чтобы взять файл по умолчанию
cli-fleet-needs-work = --fleet выполняет -c COMMANDS или run SCRIPT.lua на каждом устройстве группы
cli-hint-fleet-needs-work = например, plcsh -f { $fleet } -c 'get VW100' или plcsh run --fleet { $fleet } check.lua
shell-prompt-not-connected = нет связи
shell-complete-operating-mode = режим работы
shell-complete-open-device = открытое устройство ({ $profile }); connect NAME URL заменяет его

## Каналы, параметры и события команд K2 (shell::commands::k2cmd, events, trend, models, …)

shell-not-a-channel = `{ $num }` — не номер { $what ->
    [counter] счетчика
   *[pulse] импульсного выхода
} (0…{ $max })
shell-status-needs-channel = форме status нужен номер { $what ->
    [counter] счетчика
   *[pulse] импульсного выхода
}, например { $example }
shell-unexpected = лишнее `{ $extra }`
shell-not-a-k2 = { $name } — не ПЛК K2
shell-simulator-only = { $command } управляет симулятором; { $name } не симулируется
shell-unknown-key = неизвестный параметр `{ $key }=`
shell-hint-option-near = может быть, `{ $near }=`? параметры: { $options }; использование: { $usage }
shell-hint-option-usage = параметры: { $options }; использование: { $usage }
shell-cannot-write = не удаётся записать { $file }: { $reason }
shell-plot-not-a-size = { $key }={ $value } — не размер (2…1000 символов)
shell-plot-nothing = пока нечего рисовать
shell-hint-plot-nothing = сначала запишите, например trace SMD72 every=10ms for=2s
shell-no-events = событий нет
shell-wait-needs-event = wait требует `event N`
shell-wait-event-number = событие { $number } { $name } ({ $what }) в { $at } после ожидания { $waited }
shell-wait-event = { $name } ({ $what }) в { $at } после ожидания { $waited }
shell-wait-interrupted = ожидание { $event } прервано
shell-wait-timeout = { $event } не наступило за { $timeout }
shell-hint-wait-timeout = `events keep` перечисляет, что пришло; `pto N status` / `hsc N status` показывают, работает ли что-нибудь
shell-ports-no-arguments = ports не принимает аргументов (указано `{ $extra }`)
shell-no-ports = последовательные порты не найдены (подключите USB-адаптер и снова выполните `ports`)
shell-lua-cannot-run = здесь Lua не выполняется
shell-hint-lua-nested = строка `lua` внутри выполняющегося фрагмента Lua (plcsh.exec) не допускается; вызывайте Lua напрямую
shell-hint-fault-served = предоставляемый K2 принимает неисправности по своему каналу управления: откройте его с control=PATH (его называет строка готовности сервера)
shell-agent-il-cli = `agent il` — команда командной строки: она выводит программу-помощник для KincoBuilder
shell-hint-agent-il-cli = plcsh agent il > k2_agent.il (см. plcsh agent il --help)
shell-agent-simulator = симулятор: регистры SM и инструкции доступны напрямую (программа-помощник не нужна)
shell-wire-needs-ends = sim wire требует FROM -> TO
shell-nothing-wired = соединений нет
shell-unwire-needs-terminal = sim unwire требует клемму или `all`
shell-watch-cannot-write = не удаётся вывести результат watch: { $reason }
shell-models-columns = модель | DI/DO/DIO | AI/AO | HSC | импульсные выходы | примечания к руководству
shell-models-footer = `models MODEL` показывает одну модель полностью (области, счетчики, примечания к руководству)
shell-models-no-pulses = нет (релейные выходы)
shell-models-pto = { $output } до { $khz } кГц

## Импульсные выходы: PLS, PTO, PWM и профили (shell::commands::pulse; руководство K2 §3.4)

shell-pulse-channel-missing = не указан номер импульсного выхода: { $usage }
shell-pulse-one-channel = { $command } принимает один номер канала
shell-pulse-busy-strict = { $busy }: { $by } { $channel } заменил бы это; ничего не записано
shell-hint-pulse-busy = дождитесь окончания (pto { $channel } status), остановите (pstop { $channel }) или уберите `strict`, чтобы заменить
shell-pulse-busy-replaced = { $busy }; { $by } { $channel } заменил это (добавьте `strict`, чтобы вместо этого отказывать)
shell-freq-or-cycle = укажите freq= или cycle=, но не оба
shell-too-many-pulses = { $key }={ $value } — слишком много импульсов: PTO считает до 4 294 967 295 (§3.4.2.1)
shell-pulses-not-whole = { $key } должно быть целым положительным числом импульсов, 1 … 4 294 967 295 (указано { $key }={ $value })
shell-pto-needs-rate = pto требует freq= или cycle=
shell-pto-needs-count = pto требует count=
shell-pwm-needs-cycle = pwm требует cycle= (или freq=)
shell-pwm-needs-width = pwm требует width=
shell-pwm-negative-width = ширина импульса не может быть отрицательной
shell-segments-in-brackets = список сегментов пишется в квадратных скобках: [(cycle=500us, count=1000), …]
shell-not-a-segment = `{ $text }` — не сегмент: пишите (cycle=500us, count=1000)
shell-unexpected-in-segment = лишнее `{ $extra }` в сегменте
shell-segment-needs-rate = сегменту нужен cycle= или freq=
shell-segment-needs-count = сегменту нужен count=
shell-at-needs-address = `at` требует адрес V, например at VB3001
shell-not-a-v-byte = `{ $text }` — не адрес байта V (например, { $example })
shell-profile-needs-at = profile требует `at VBxxxx` (нечетный адрес V)
shell-profile-needs-segments = profile требует список сегментов [(cycle=…, count=…), …]
shell-profile-series = частота PTO{ $channel }
shell-profile-plan-title = план профиля PTO{ $channel }: { $pulses } { $pulses ->
    [one] импульс
    [few] импульса
   *[many] импульсов
}, { $segments } { $segments ->
    [one] сегмент
    [few] сегмента
   *[many] сегментов
}
shell-profile-plan-segment = сегмент { $segment }: { $from }–{ $to } с  { $hz } Гц  { $pulses } { $pulses ->
    [one] импульс
    [few] импульса
   *[many] импульсов
}
shell-profile-plan-total = всего: { $pulses } { $pulses ->
    [one] импульс
    [few] импульса
   *[many] импульсов
} за { $seconds } с; ничего не записано (уберите `plan`, чтобы выполнить)

## Высокоскоростные счетчики и область резервного копирования в E2PROM (shell::commands::counter, eeprom; руководство K2 §3.3, §2.2.8)

shell-hsc-not-a-number = `{ $text }` — не { $what ->
    [mode] номер режима
    [cv] текущее значение DINT
   *[pv] предустановленное значение DINT
}
shell-hdef-needs-two = hdef принимает номер счетчика и режим
shell-hsc-needs-counter = hsc требует номер счетчика
shell-hsc-needs-mode = настройке hsc нужен mode=
shell-hsc-dir = dir={ $value }: используйте up или down
shell-hsc-level = { $key }={ $value }: активный уровень — high или low
shell-at-needs-v-address = `at` требует адрес V
shell-eeprom-saved = VB{ $first }…VB{ $last } ({ $bytes } { $bytes ->
    [one] байт
    [few] байта
   *[many] байт
}) сохранено в { $file }
shell-cannot-read = не удаётся прочитать { $file }
shell-eeprom-too-big = в { $file } { $bytes } { $bytes ->
    [one] байт
    [few] байта
   *[many] байт
}, а в области резервного копирования данных VB{ $first }…VB{ $last } — { $room }
shell-hint-eeprom-area = сначала расширьте область: eeprom area 4095
shell-eeprom-restored = { $bytes } { $bytes ->
    [one] байт восстановлен
    [few] байта восстановлены
   *[many] байт восстановлено
} в VB{ $first }…VB{ $last } из { $file }
shell-eeprom-area-size = область резервного копирования данных VB{ $first }…VB{ $last } ({ $bytes } { $bytes ->
    [one] байт
    [few] байта
   *[many] байт
})
shell-eeprom-hottest = чаще всего записываемый байт VB{ $byte }: { $writes } { $writes ->
    [one] запись
    [few] записи
   *[many] записей
} ({ $share } % из ~{ $endurance })
shell-eeprom-wear = при темпе этого сеанса ({ $rate } записей/с виртуального времени) он износится через { $left }
shell-eeprom-wear-warning = так E2PROM износится меньше чем за 10 лет; не держите часто меняющиеся данные в области резервного копирования данных (§2.2.8)
shell-eeprom-no-writes = записей не подсчитано
shell-eeprom-area = область резервного копирования данных VB{ $first }…VB{ $last }
shell-one-file-only-plain = { $form } принимает один файл, а не { $count } { $count ->
    [one] слово
    [few] слова
   *[many] слов
}
shell-eeprom-unknown = неизвестная команда eeprom

## Часы, входы и сохраняемые диапазоны симулятора (shell::commands::sim, siminputs)

shell-sim-step-form = sim step DURATION (например, sim step 1s, sim step 500ms)
shell-unexpected-after-sim = лишнее `{ $extra }` после `sim { $sub }`
shell-sim-step-needs-duration = sim step требует длительность, например sim step 500ms
shell-sim-time-forward = время движется только вперёд
shell-sim-step-too-far = sim step { $step } увёл бы часы симулятора за { $latest } с (около 584 лет) — наибольшее время, которое они считают
shell-sim-clock-graded = `sim clock real` недоступна при оценке работы: её часы симулируются
shell-hint-sim-clock-graded = ждите через sim step DURATION или plcsh.sleep(ms)
shell-sim-not-clock-mode = `{ $mode }` — не режим часов
shell-hint-sim-clock-modes = sim clock real (идти по реальным часам) | sim clock stepped (двигаться только через sim step)
shell-sim-run-ambiguous = `sim run` неоднозначна: скажите, что запустить
shell-hint-sim-run-ambiguous = sim clock real: время идёт по часам; sim cpu run: выполняется программа
shell-sim-cli-only = `sim { $sub }` — команда командной строки, а не оболочки
shell-hint-sim-cli-only = в другом терминале: plcsh sim { $sub } … (plcsh sim { $sub } --help перечисляет её параметры)
shell-hint-fault-clear = sim fault clear (все неисправности) | sim fault clear 2 (неисправность 2; `sim faults` перечисляет номера)
shell-not-a-fault-id = `{ $id }` — не номер неисправности: форма команды — { $form }
shell-sim-unknown = неизвестная `sim { $sub }`
shell-sim-time = время симулятора { $time } ({ $mode ->
    [stepped] шагами
   *[wall] по реальным часам
})
shell-not-an-input-bit = `{ $text }` — не бит входа (например, I0.1)
shell-signal-needs-freq = сигналу нужен freq=, например freq=1kHz
shell-signal-freq = freq={ $value }: целое число Гц до 10 МГц
shell-sim-inputs-alone = после sim inputs ничего не пишется (указано `{ $extra }`)
shell-no-input-signals = симулируемых входных сигналов нет
shell-retain-none-alone = `sim retain none` пишется отдельно (рядом указано `{ $extra }`)
shell-hint-retain-forms = sim retain none (ничего не сохранять) | sim retain VB0..VB99 MB0[8] (эти диапазоны)
shell-no-retained = сохраняющихся диапазонов нет
shell-retained = сохраняются: { $ranges }
shell-signal-stopped = остановлено: { $signal }
shell-no-direction-input = у { $input } нет входа направления: dir= относится к I0.1 (направление I0.5) и I0.3 (направление I0.2)
shell-direction-input = ; вход направления { $input } = { $value }
shell-quad-needs-two = sim quad требует два входа: A (опережающий) и B
shell-quad-same-input = A и B должны быть разными входами
shell-quad-dir = dir={ $value }: используйте up (опережает A) или down (опережает B)

## Списки: устройства, пути, порты; run, completions и man командной строки (shell::commands, cli)

shell-devices-read-only = только чтение
shell-devices-per-profile = по профилю каждого
shell-devices-count = { $count } { $count ->
    [one] устройство
    [few] устройства
   *[many] устройств
}
shell-devices-profile-problem = файл профилей: { $problem }
shell-paths-columns = файл | путь | чем задан
shell-ports-columns = порт | вид | usb id | адаптер | серийный номер
cli-run-no-lua = не удаётся запустить Lua: { $reason }
cli-run-no-sandbox = не удаётся подготовить песочницу: { $reason }
cli-completions-cannot-write = plcsh: не удаётся записать скрипты дополнения в { $dir }: { $reason }
cli-completions-name-a-shell = plcsh completions: укажите оболочку (bash, zsh, fish, powershell) или --write DIR
cli-completions-wrote = записан { $file }
cli-man-manual = руководство plcsh

## Симулируемый CPU: программы, циклы сканирования, точки останова; симулятор FX (shell::commands::simprogram, fxsim)

shell-sim-no-program = { $name }: программа не загружена (sim program load FILE.il)
shell-sim-cpu = { $name }: CPU { $mode }{ $switch ->
    [stop] { " " }(переключатель в положении STOP)
   *[run] { "" }
}
shell-sim-loaded = { $what ->
    [helper] программа-помощник
   *[program] программа
}: { $source } ({ $instructions } { $instructions ->
    [one] инструкция
    [few] инструкции
   *[many] инструкций
})
shell-sim-scans = циклов сканирования { $scans }; время сканирования последнее { $last } мс, мин. { $min } мс, макс. { $max } мс (SMW22/24/26); { $instructions } { $instructions ->
    [one] инструкция
    [few] инструкции
   *[many] инструкций
} в последнем цикле; выполнено подпрограмм прерываний: { $interrupts }
shell-sim-costs = сторожевой таймер { $watchdog } мс, минимальный цикл сканирования { $min_scan } мс, накладные расходы { $overhead } мс
shell-sim-stopped-by-program = остановлено инструкцией STOP программы (sim cpu run запускает снова)
shell-sim-fault = неисправность в { $at } с: { $fault }
shell-sim-err-led = светодиод Err горит: { $count } { $count ->
    [one] обычная ошибка
    [few] обычные ошибки
   *[many] обычных ошибок
} (CPU продолжает работу); последняя в { $at } с: { $error }
shell-sim-cpu-needs-mode = sim cpu требует run, stop или pause
shell-sim-load-needs-file = sim program load требует файл, например { $example }
shell-cannot-read-because = не удаётся прочитать { $file }: { $reason }
shell-sim-stop-values = значения в STOP: { $values }
shell-sim-program-unknown = неизвестная `sim program { $sub }`
shell-sim-switch-form = sim switch run|stop (симулируемый переключатель RUN/STOP)
shell-sim-scan-count = sim scan N: N — число циклов сканирования 1…10000000, а не `{ $text }`
shell-sim-no-breakpoints = точек останова нет
shell-sim-breakpoints = { $count ->
    [one] точка останова в строке
   *[other] точки останова в строках
} { $lines }
shell-sim-breakpoints-cleared = точки останова удалены
shell-sim-stepi-count = sim stepi N: N — от 1 до 100000, а не `{ $text }`
shell-fx-program = { $name }: { $model } { $mode }; программа { $program } ({ $instructions } { $instructions ->
    [one] инструкция
    [few] инструкции
   *[many] инструкций
})
shell-fx-no-program = { $name }: { $model } { $mode }; программы нет (sim program load FILE.il)
shell-fx-scans = циклов сканирования { $scans }; время сканирования последнее { $last } мс, мин. { $min } мс, макс. { $max } мс (D8010/D8011/D8012); время { $time } с
shell-fx-fault = остановлено неисправностью: { $fault }
shell-fx-not-simulator = это не симулятор FX
shell-fx-real = настоящий FX выполняет свою программу
shell-fx-loaded = { $file }: { $instructions } { $instructions ->
    [one] инструкция загружена
    [few] инструкции загружены
   *[many] инструкций загружено
}; ПЛК перезапускается в режиме RUN
shell-fx-unloaded = программа удалена: ПЛК сканирует пустую программу
shell-fx-program-unknown = неизвестная `sim program { $sub }` для ПЛК FX
shell-fx-no-pause = у ПЛК FX есть RUN и STOP, но нет PAUSE
shell-fx-cpu-needs-mode = sim cpu требует run или stop
shell-fx-mode = { $model } в режиме { $mode }
shell-fx-sim-unavailable = `sim { $sub }` недоступна для ПЛК FX

## Учебный ПЛК УМПК (shell::commands::umpk; руководство УМПК8/16)

shell-umpk-not-umpk = `{ $name }` — не УМПК
shell-umpk-none-open = ни один УМПК не открыт
shell-hint-umpk-open = откройте его через --device lab=umpk:{ $port } или connect lab sim-umpk:UMPK16
shell-umpk-several = открыто несколько УМПК; укажите один (umpk NAME info)
shell-umpk-needs-subcommand = umpk требует подкоманду
shell-umpk-program-info-none = сведения о программе (22 пробела: программы нет, режим «Ожидание»)
shell-umpk-program-info = сведения о программе "{ $info }"
shell-umpk-timing = самый долгий цикл { $total } мкс, встроенное ПО { $firmware } мкс, программа { $program } мкс (T = (LLMM − HHKK) × 0.271 мкс; HHKK={ $hhkk } LLMM={ $llmm })
shell-umpk-reset = сброс: контроллер перезапущен (получен R; эхо включено)
shell-umpk-unknown = неизвестная `umpk { $sub }`
shell-umpk-real-program = настоящий УМПК выполняет только то, что в него запрограммировано (umpk program FILE.hex); программы IL выполняются в симуляторе
shell-umpk-il-loaded = { $file }: { $instructions } { $instructions ->
    [one] инструкция загружена
    [few] инструкции загружены
   *[many] инструкций загружено
}; выполняется каждый цикл ПЛК { $cycle } мс в режиме «Работа»
shell-umpk-sim-program-unknown = неизвестная `sim program { $sub }` для УМПК
shell-hint-umpk-sim-program = sim program load FILE.il | sim program
shell-umpk-program-mode = программа: { $program }; режим { $mode }
shell-umpk-info-columns = поле | значение
shell-umpk-info-fields = модель | встроенное ПО | входы / выходы | режим | слово состояния | микрокод | эхо | программа (симулятор)
shell-umpk-no-flag = флаги не установлены
shell-umpk-mode = { $mode ->
    [Programming] «Программирование»
    [Work] «Работа»
   *[Wait] «Ожидание»
}
shell-umpk-errors-cleared = история ошибок очищена
shell-umpk-errors-empty = история ошибок пуста
shell-umpk-errors-columns = # | код | значение (сначала новые; 1–127 пользовательские, 128–255 системные)
shell-umpk-send-needs = umpk send требует команду или запись, например umpk send ?03FD
shell-umpk-sim-needs-simulator = umpk sim работает с симулируемым УМПК: внутри процесса (sim-umpk:UMPK16) или предоставляемым через plcsh sim serve --umpk-pty LINK и открытым с control=LINK.ctl; входы настоящего УМПК подключаются проводами
shell-umpk-reference-in-process = эталонные программы загружаются в симулятор внутри процесса (sim-umpk:UMPK16)
shell-umpk-no-reference = нет эталонной программы `{ $name }`
shell-hint-umpk-references = эталонные программы: { $names }
shell-umpk-reference-loaded = эталонная программа { $name } загружена ({ $description }); режим { $mode }
shell-umpk-program-needs-file = umpk program требует файл HEX
shell-umpk-program-extra = лишнее `{ $extra }` (после файла может быть только `run`)
shell-umpk-info-text = info="{ $info }": 1–22 печатных символа ASCII (руководство, §4.2.4)
shell-hint-umpk-hex = ничего не отправлено; { $model } принимает записи 00/01/02/03 в пределах 16#0000..16#{ $last }
shell-umpk-programmed-run = сброс: программа включена (режим «Работа»)
shell-umpk-programmed-stays = контроллер остаётся в режиме «Программирование»; `umpk reset` включает программу
shell-umpk-programmed = записано { $bytes } { $bytes ->
    [one] байт
    [few] байта
   *[many] байт
} на { $pages } { $pages ->
    [one] страницу
    [few] страницы
   *[many] страниц
}, подтверждено записей: { $records }{ $named ->
    [yes] , сведения о программе "{ $info }"
   *[no] { "" }
}{ $stopped ->
    [yes] ; контроллер был в режиме «Работа»: с началом программирования его программа остановилась, а выходы отключились
   *[no] { "" }
}; { $next }
shell-umpk-monitor-stopped = поток монитора реального времени прекратился (нет пакета в пределах тайм-аута)
shell-umpk-monitor-cannot-write = не удаётся вывести данные монитора: { $reason }
shell-umpk-monitor-samples = { $samples } { $samples ->
    [one] выборка
    [few] выборки
   *[many] выборок
} монитора из { $packets } { $packets ->
    [one] пакета
   *[other] пакетов
}

## Группы, probe, записи и предоставляемые симуляторы командной строки (cli::fleet, probe, record, serve)

cli-device-timeout-bad = --device-timeout { $value } — не длительность
cli-hint-device-timeout = например, 30s, 2m, 500ms; 0 — без ограничения
cli-jobs-at-least-one = --jobs должно быть не меньше 1
cli-fleet-all-refused = { $message } (все устройства группы `{ $fleet }` отказали; ничего не выполнено)
cli-fleet-no-sandbox = --sandbox работает только с симулируемыми устройствами, а не с группой
cli-hint-fleet-no-sandbox = оценивайте работы через plcsh lab grade или запускайте скрипт группы без --sandbox
cli-fleet-checks = проверок пройдено: { $passed }, не пройдено: { $failed }
cli-agent-check-read-only = agent check записывает почтовый ящик программы-помощника и байты SM одного импульсного выхода, а --read-only запрещает любые изменения
cli-agent-check-profile = agent check записывает почтовый ящик программы-помощника и байты SM одного импульсного выхода, а профиль `{ $profile }` ({ $origin }) ограничивает запись
cli-hint-agent-check-writes = запускайте её без --read-only, с URL ПЛК, когда установку безопасно проверять (docs/reference/first-connection.md перечисляет, что она записывает)
cli-probe-in-process = { $url } — симулятор внутри процесса: на линии связи нечего проверять
cli-hint-probe-in-process = предоставьте его и проверяйте уже его: plcsh sim serve --tcp 127.0.0.1:0 [--agent], затем plcsh probe tcp://ADDRESS
cli-probe-not-on-wire = `{ $scheme }:` — не K2 на линии связи
cli-hint-probe-urls = укажите tcp://HOST:PORT, rtu:PORT?baud=…, rtu+tcp://HOST:PORT или rtu+rfc2217://HOST:PORT
cli-probe-cannot-write-report = не удаётся записать отчёт в { $file }
cli-replay-bench-options = replay --bench запускает собственные симуляторы стенда: --sim-model и --snapshot не применяются
cli-hint-replay-bench-options = измените модель или начальные значения в файле стенда
cli-replay-no-device = replay отправляет записанные запросы только симуляторам, которые создаёт сама, и никогда — на --device
cli-hint-replay-no-device = модель симулятора выбирается через --sim-model, начальное состояние — через --snapshot
cli-replay-no-reply = (нет ответа)
cli-replay-recorded = записано: { $reply }
cli-replay-replayed = при повторе: { $reply }
cli-replay-skipped = не повторено: { $what }
cli-replay-summary = повторено запросов: { $requests }, различий: { $differences }
cli-record-damaged = plcsh: предупреждение: { $file }: { $doing ->
    [replaying] повторяются
   *[showing] показываются
} { $frames } { $frames ->
    [one] кадр, прочитанный
    [few] кадра, прочитанных
   *[many] кадров, прочитанных
} вокруг повреждения; код завершения 1
cli-record-truncated = plcsh: предупреждение: { $file } обрывается раньше времени ({ $why }); { $doing ->
    [replaying] повторяются
   *[showing] показываются
} { $frames } { $frames ->
    [one] кадр
    [few] кадра
   *[many] кадров
} до обрыва
cli-serve-not-an-address = `{ $text }` — не адрес для прослушивания
cli-hint-serve-address = используйте HOST:PORT (127.0.0.1:5020, 0.0.0.0:502) или порт (5020; 0 — выбрать свободный)
cli-serve-cannot-listen = не удаётся слушать { $addr }
cli-hint-serve-port = выберите другой порт (0 — свободный); для портов ниже 1024 нужны права
cli-serve-fault-acted = plcsh sim serve: { $line }
cli-serve-idle-timeout = --idle-timeout { $value } — не длительность
cli-hint-serve-idle-timeout = например, 300s, 2m
cli-serve-servo-latency = --servo-latency { $value }: не длительность
cli-hint-serve-servo-latency = например, 1ms, 500us, 0
cli-serve-servo-baud = --servo-baud должно быть положительным (например, 38400)
cli-serve-servo-line-stopped = линия сервоприводов остановилась, не успев подготовиться
cli-serve-needs-transport = sim serve требует хотя бы один транспорт
cli-hint-serve-transport = например, plcsh sim serve --tcp 127.0.0.1:5020 --rtu-tcp 0 --servo-tcp 0 (в Unix также --rtu-pty /tmp/k2 --servo-pty /tmp/kinco)
cli-serve-agent-needs-k2 = --agent выполняется в предоставляемом K2: укажите также --tcp, --rtu-pty или --rtu-tcp
cli-serve-no-signals = не удаётся установить обработчики сигналов
cli-serve-no-readiness = не удаётся вывести строку готовности
cli-serve-server-stopped = сервер остановился
cli-serve-failed = предоставление симуляторов прервалось с ошибкой
cli-serve-no-runtime = не удаётся запустить среду выполнения
cli-serve-fleet-state = --state с --fleet: симуляторы делили бы один файл состояния
cli-hint-serve-fleet-state = уберите --state (предоставляемая группа не хранит состояние)
cli-serve-fleet-bench = --bench с --fleet: стенд описывает одну установку
cli-serve-fleet-ports = --tcp { $tcp } --fleet { $count }: порты выходят за 65535
cli-serve-fleet-member-stopped = поток одного из устройств группы остановился
cli-serve-rfc2217-needs-tcp = --rfc2217 относится к последовательным линиям, предоставляемым по TCP
cli-hint-serve-rfc2217 = укажите также --rtu-tcp, --servo-tcp, --fx-tcp, --fx-link-tcp или --umpk-tcp, например --rtu-tcp 0 --rfc2217

## Сервоприводы Kinco (shell::commands::servo; описание протокола RS232 сервоприводов Kinco, состояния CiA 402)

shell-usage-line = использование: { $line }
shell-servo-needs-subcommand = servo требует подкоманду
shell-servo-nothing-after = после servo { $sub } ничего не пишется (указано `{ $extra }`)
shell-servo-already-enabled = уже в состоянии operation enabled
shell-servo-enabled = operation enabled ({ $steps })
shell-servo-mode-needs = servo mode требует режим: position, velocity, immediate-velocity, homing, torque или pulse
shell-servo-unknown-mode = неизвестный режим `{ $mode }`
shell-hint-servo-modes = position (1), velocity (3), immediate-velocity (-3), homing (6), torque (4), pulse (-4)
shell-servo-mode-set = режим работы { $number } ({ $name })
shell-servo-halted = остановлено: торможение до останова и удержание (controlword 16#{ $controlword })
shell-servo-halt-released = останов снят: движение продолжается (controlword 16#{ $controlword })
shell-servo-homing = возврат в исходное положение начат (режим 6, controlword 16#000F → 16#001F)
shell-servo-saved = параметры сохранены (2FF0.01 = 1)
shell-servo-not-servo = `{ $name }` — не сервопривод
shell-servo-none-open = ни один сервопривод не открыт
shell-hint-servo-open = откройте его через --device ax=kinco:{ $port }?id=1 или connect ax sim-servo:?id=1
shell-servo-several = открыто несколько сервоприводов; укажите один
shell-hint-servo-several = servo { $first } status (открыты: { $names })
shell-servo-not-whole = `{ $key }={ $value }` — не целое число
shell-hint-servo-options = параметры: { $options }
shell-servo-move = { $kind ->
    [rel] относительное
   *[abs] абсолютное
} перемещение в { $target } inc начато
shell-servo-move-speed = { $kind ->
    [rel] относительное
   *[abs] абсолютное
} перемещение в { $target } inc начато со скоростью { $rpm } об/мин ({ $dec } DEC)
shell-servo-jog-usage = использование: servo jog SPEED [acc=… dec=…], например servo jog 300rpm; servo jog 0 останавливает
shell-servo-jogging = толчковое движение со скоростью { $rpm } об/мин ({ $dec } DEC, режим 3)
shell-servo-over-max = { $rpm } об/мин больше максимальной скорости привода { $max } об/мин (6080.00 max_speed)
shell-hint-servo-max = скорость до { $max }rpm; максимум задаётся настройкой привода 6080.00 (servo read max_speed)
shell-hint-servo-wait = servo wait target timeout=5s
shell-servo-target-reached = цель достигнута через { $seconds } с (position_actual { $position } inc)
shell-servo-read-needs = servo read требует объекты, например servo read target_velocity position_actual
shell-servo-read-columns = объект | индекс | значение | единица | в технических единицах
shell-servo-encoder = разрешение энкодера { $resolution } inc/об
shell-servo-not-hex-byte = `{ $text }` — не шестнадцатеричный байт
shell-servo-frame-length = кадр — это 9 байт (контрольная сумма добавляется) или 10 байт, а не { $count }
shell-hint-servo-raw = например, servo raw 01 40 41 60 00 00 00 00 00
shell-servo-sim-needs = servo sim требует команду управления
shell-servo-sim-needs-simulator = servo sim работает с симулируемыми приводами: внутри процесса (sim-servo:), предоставляемыми через plcsh sim serve --servo-pty LINK или через --servo-tcp ADDR --servo-control PATH и открытыми с control=PATH
shell-hint-servo-sim-control = канал управления предоставляемого привода — LINK.ctl; если он в другом месте, укажите control=PATH в URL kinco:
shell-servo-unknown = неизвестная `servo { $sub }`
