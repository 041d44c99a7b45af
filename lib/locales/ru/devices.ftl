# plcsh messages (ru): devices — драйверы и симуляторы сервопривода, УМПК и FX, линии связи. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## UMPK terminal protocol (umpk::codec; UMPK manual §4.1, §4.2, Tables 6 and 8)

# The manual's names of the terminal commands (Table 6).
umpk-command-name = { $command ->
    [reset] сброс контроллера
    [echo-on] включить эхо
    [echo-off] выключить эхо
    [info] информация о контроллере
    [program-info] информация о программе
    [inputs] отобразить состояние входов
    [outputs] отобразить состояние выходов
    [errors] показать историю ошибок
    [clear-errors] сброс истории ошибок
    [programming] переход в режим программирования
    [monitor-start] старт монитора реального времени
    [monitor-stop] стоп монитора реального времени
   *[timing] временные характеристики ПЛК
    }
umpk-form-short-command = в `{ $text }` после ? { $count ->
        [one] { $count } символ
        [few] { $count } символа
       *[many] { $count } символов
    }, а УМПК ждёт четыре: терминальная команда — это ? и четыре шестнадцатеричные цифры, код команды и контрольная сумма, дополняющая его до 100 hex
umpk-form-short-command-like = в `{ $text }` после ? { $count ->
        [one] { $count } символ
        [few] { $count } символа
       *[many] { $count } символов
    }, а УМПК ждёт четыре: терминальная команда — это ? и четыре шестнадцатеричные цифры, код команды и контрольная сумма, дополняющая его до 100 hex; для команды «{ $command }» отправьте { $bytes }
umpk-form-no-reclen = `{ $text }` не начинается с длины записи (две шестнадцатеричные цифры после :): терминальная команда — это ? и четыре шестнадцатеричные цифры, код команды и контрольная сумма, дополняющая его до 100 hex (например, ?03FD — информация о контроллере); запись HEX — это : RECLEN OFFSET TYPE DATA CHECKSUM в шестнадцатеричном виде (например, :00000002FE — начать процесс программирования)
umpk-form-record-length = в `{ $text }` { $count ->
        [one] { $count } символ
        [few] { $count } символа
       *[many] { $count } символов
    }, а запись HEX с RECLEN { $reclen } имеет длину { $want }: : RECLEN(2) OFFSET(4) TYPE(2) DATA({ $data }) CHECKSUM(2), например :00000002FE (начать процесс программирования)
umpk-form-neither = `{ $text }` — не терминальная команда УМПК и не запись HEX: терминальная команда — это ? и четыре шестнадцатеричные цифры, код команды и контрольная сумма, дополняющая его до 100 hex (например, ?03FD — информация о контроллере); запись HEX — это : RECLEN OFFSET TYPE DATA CHECKSUM в шестнадцатеричном виде (например, :00000002FE — начать процесс программирования)
umpk-status-bits-not-six = `{ $text }` — не шесть номеров битов 0–7 для W,H,R,E,P,T (например, 5,4,3,2,1,0)
umpk-status-bits-count = `{ $text }` должно называть шесть битов, для W,H,R,E,P,T (например, 5,4,3,2,1,0)
umpk-status-bits-twice = бит { $bit } указан в `{ $text }` дважды
# The meaning of an error-history code (§4.1.8).
umpk-error-none = нет ошибки
umpk-error-user = ошибка пользователя { $code } (установлена программой)
umpk-error-output-overflow = системная ошибка 255: переполнение буфера вывода — команда передана до завершения приёма предыдущего ответа (§4.1)
umpk-error-cycle-overrun = системная ошибка 254 (симулятор plcsh: программа не уложилась в цикл 10 мс и остановлена; режим «Ожидание» до сброса)
umpk-error-program-fault = системная ошибка 253 (симулятор plcsh: программа остановлена из-за неисправности; режим «Ожидание» до сброса)
umpk-error-system = системная ошибка { $code }
# What each reply letter means (§4.1, §4.2).
umpk-letter = { $letter ->
    [E] E: ошибка контрольной суммы — контрольная сумма команды не совпадает с её байтами
    [U] U: неизвестная команда
    [C] C: команда содержит недопустимый символ
    [L] L: длина данных в записи превышает допустимую (64 байта на страницу, 22 байта информации о программе)
    [A] A: нарушена последовательность адресов или адрес вне диапазона — страницы должны идти одна за другой внутри памяти программ
    [W] W: ошибка IAP-операции записи во flash-память
    [X] X: операции программирования сейчас запрещены (ПЛК не в режиме «Программирование», ещё не было записи начала или предыдущая запись не удалась)
   *[other] неизвестный символ ответа
    }
# What came instead of a reply (umpk::codec::parse_exchange).
umpk-bad-monitor-packet = повреждённый пакет монитора: { $bytes }
umpk-bad-r-cr = после `R` CR пришло { $bytes }
umpk-bad-echo = эхо { $echo } отличается от команды { $sent }
umpk-bad-length-field = пакет с неверным полем длины: { $bytes }
umpk-bad-packet-length = пакет из { $got ->
        [one] { $got } байта
       *[other] { $got } байтов
    }, а ожидалось { $want }
umpk-bad-packet-hex = пакет с нешестнадцатеричными символами: { $bytes }
umpk-bad-packet-checksum = пакет с неверной контрольной суммой: { $bytes } (ожидалось { $expected })
umpk-bad-reply = неожиданный ответ { $bytes }
umpk-bad-crlf = ответ не заканчивается на CR LF: { $bytes }

## UMPK driver (umpk::driver)

umpk-no-complete-reply = нет полного ответа на { $sent } от УМПК на { $link } за { $timeout }
umpk-no-complete-reply-partial = нет полного ответа на { $sent } от УМПК на { $link } за { $timeout }; пришло только { $partial }
umpk-hint-silent = проверьте питание, кабель RS-232 (≤ 2 м) и 57600 8N1; контроллер во время сброса молчит ~0,6 с
umpk-unexpected-reply = неожиданный ответ на { $sent } на { $link }: { $what }
umpk-hint-garbled = возможно, порт занят другой программой или скорость передачи данных не 57600
umpk-refused-command = УМПК отказал в выполнении ?{ $code } ({ $command }): { $letter }
umpk-hint-programming-mode = в режиме «Программирование» УМПК отвечает только на сброс, включение/выключение эха и информацию о контроллере (таблица 6 руководства); `umpk reset` выводит из режима «Программирование»
umpk-hint-corrupted = линия искажает байты: проверьте кабель и 57600 8N1
umpk-answered-other = УМПК ответил { $reply } на ?{ $code } ({ $command })
umpk-packet-size = { $what ->
    [info] пакет информации о контроллере не из шести байтов
    [errors] пакет истории ошибок не из восьми байтов
    [timing] пакет временных характеристик не из четырёх байтов
   *[other] ожидался пакет из 4 байтов
    }
umpk-no-monitor-packet = нет пакета монитора реального времени от УМПК на { $link } за { $timeout }
umpk-send-empty = umpk send нужна команда (?03FD) или запись (:00000002FE)
umpk-not-sent = не отправлено УМПК на { $link }: { $reason }
umpk-refused-record = УМПК отказал в записи { $n } из { $total } ({ $record ->
        [start] запись начала программирования
        [info] запись информации о программе
        [end] запись конца программирования
       *[data] страница данных по адресам 16#{ $first }..16#{ $last }
    }): { $letter }
umpk-hint-program-incomplete = программирование прервано, новая программа записана не полностью: повторите `umpk program FILE` с начала; контроллер остаётся в режиме «Программирование» (`umpk reset` переводит его в «Ожидание»)
umpk-answered-record = УМПК ответил { $reply } на запись HEX
umpk-unknown-model-reported = контроллер сообщает модель { $model } с { $inputs } входами и { $outputs } выходами — это ни одна из { $models }
umpk-model-mismatch = указано model={ $given }, но контроллер — { $found }
umpk-hint-model-mismatch = уберите model= или укажите model={ $found }
umpk-not-writable = в терминальном протоколе УМПК нет команд записи (§4.1 руководства, таблица 6), поэтому { $operand } установить нельзя
umpk-hint-not-writable = входы задаются подключением, а выходы, таймеры, счетчики и маркеры принадлежат программе; на симуляторе используйте `umpk sim input I3=1`
umpk-no-option = у устройств УМПК нет параметра `{ $key }`
umpk-hint-options = параметры: timeout, status_bits
umpk-not-model = `{ $model }` в { $url } — не модель УМПК
umpk-hint-models = модели: { $models }
umpk-baud-zero = `baud=0` в { $url }: скорость передачи данных должна быть больше нуля
umpk-cannot-read-program = { $url }: не удаётся прочитать { $file }: { $reason }

## UMPK operands (umpk::space; UMPK manual §3.3–§3.5)

# What an area holds (`help I0`, completion).
umpk-area-meaning = { $area ->
    [I] дискретный вход
    [Q] дискретный выход (оптореле, 48 В 0,3 А)
    [T] выход таймера задержки включения
    [C] выходной импульс счетчика
   *[M] маркер
    }
# Where plcsh reads an area from.
umpk-area-source = { $area ->
    [I] ?05FB или монитор
    [Q] ?06FA или монитор
   *[other] монитор реального времени
    }
umpk-not-operand = `{ $text }` — не операнд УМПК
umpk-hint-operands = операнды УМПК: I0…, Q0…, M0…, T0…, C0…C3 (подробнее: help I0)
umpk-number-must-follow = `{ $text }`: после { $letter } должен идти номер (например, { $letter }0)
umpk-past-end = { $operand } вне диапазона: у { $model } есть { $letter }0…{ $letter }{ $last }
umpk-not-range = `{ $text }` — не диапазон одной области (например, I0..I7)
umpk-describe = { $meaning } { $operand } (читается через { $source })
umpk-help-operand = { $operand }: { $meaning } { $model } ({ $letter }0…{ $letter }{ $last }); BOOL; читается через { $source }; руководство, { $section }. В терминальном протоколе УМПК нет команд записи.
## UMPK Intel HEX files (umpk::hex; UMPK manual §4.2, Appendix 1)

umpk-hex-no-colon = запись начинается с `:`
umpk-hex-not-hex-digit = символ { $position } записи — не шестнадцатеричная цифра
umpk-hex-odd-digits = в записи должно быть нечётное число шестнадцатеричных цифр, не меньше 10; в этой { $count }
umpk-hex-reclen = RECLEN указывает { $reclen } байт данных, а в записи { $count }
umpk-hex-checksum = контрольная сумма { $got }, а для этих байтов нужна { $want }
umpk-hex-line = строка { $line }: { $message }
umpk-hex-after-end = строка { $line }: запись после записи конца (01)
umpk-hex-outside-memory = строка { $line }: данные по адресам 16#{ $first }..16#{ $last } вне памяти программ (16#0000..16#{ $top }, { $memory } байт)
umpk-hex-twice = строка { $line }: адрес 16#{ $address } записан дважды
umpk-hex-type-02 = строка { $line }: запись типа 02 с данными ({ $count } байт): УМПК принимает тип 02 только как запись начала программирования без данных (:00000002FE, её отправляет сам plcsh); в стандартном Intel HEX это расширенный адрес сегмента, который программе не больше 3 КБ не нужен — удалите строку
umpk-hex-info-size = строка { $line }: информация о программе занимает 1–22 байта, а не { $count }
umpk-hex-record-type = строка { $line }: тип записи { $rtype } УМПК не принимает (00 — данные, 01 — конец, 02 — начало, 03 — информация о программе)
umpk-hex-no-end = в файле нет записи конца (:00000001FF)
umpk-hex-no-data = в файле нет записей данных

## The simulated UMPK's control words (umpk::sim::control; `umpk sim …`, the control channel)

umpk-sim-hint-words = управляющие слова: { $words }
umpk-sim-not-input = `{ $text }` — не вход (I0…I{ $last })
umpk-sim-no-such-input = I{ $n } — не вход { $model } (I0…I{ $last })
umpk-sim-input-usage = input нужны вход и уровень: input I3=1
umpk-sim-input-extra = `{ $word }` после input I{ $n } не понято
umpk-sim-level-and-freq = укажите уровень или freq=, но не оба сразу
umpk-sim-freq-range = freq={ $freq }: цикл 10 мс различает меандр частотой 0,0001–50 Гц
umpk-sim-wave-set = I{ $n }: меандр, период { $period } мс
umpk-sim-not-input-option = `{ $option }` — не параметр входа (freq=)
umpk-sim-level-missing = I{ $n }: укажите =1, =0 или freq=…
umpk-sim-inputs-extra = после `inputs` ничего не указывается (получено `{ $word }`)
umpk-sim-inputs = входы { $bits } (I{ $last }…I0); меандр на { $waves }
umpk-sim-inputs-no-waves = входы { $bits } (I{ $last }…I0); меандра нет ни на одном входе
umpk-sim-not-page = `{ $page }` — не номер страницы
umpk-sim-flash-fail = запись во flash-память на страницу { $page } (16#{ $address }) будет завершаться ошибкой W
umpk-sim-flash-ok = запись во flash-память выполняется успешно
umpk-sim-not-word = `{ $word }` — не управляющее слово симулятора УМПК
umpk-sim-empty-line = пустая управляющая строка

## Snapshots of the simulated UMPK (umpk::sim::snapshot): why one cannot be taken or restored

umpk-snap-monitor = его монитор реального времени передаёт данные (сначала остановите его: `umpk monitor off`)
umpk-snap-programming = идёт процесс программирования (сначала завершите его или выполните сброс)
umpk-snap-line-busy = на его последовательном порту есть байты (команда принята не полностью или ответ не отправлен)
umpk-snap-builtin-program = его программа `{ $program }` встроена в plcsh, это не текст IL (загрузите вместо неё файл IL)
umpk-snap-other-model = в снимке { $saved }, а это устройство — { $model }
umpk-snap-flash-size = образ flash-памяти неверного размера
umpk-snap-info-size = информация о программе или история ошибок неверного размера
umpk-snap-markers = маркеры — не 32 шестнадцатеричные цифры
umpk-snap-timers = таймеры или счетчики не соответствуют модели
umpk-snap-wave = меандр на входе { $input } с периодом { $period } циклов невозможен на этой модели
umpk-snap-flash-fail-page = его сбойная страница flash-памяти { $page } вне памяти программ модели
umpk-snap-fault-input = его неисправность { $fault } относится ко входу, которого у этой модели нет
umpk-snap-cycle-ahead = его счетчик циклов опережает часы снимка
umpk-snap-mode = режим `{ $mode }` восстановить нельзя
umpk-snap-il-compile = его программа IL { $source } не компилируется: { $reason }
umpk-snap-il-state = сохранённое состояние его программы IL не подходит к программе ({ $part })
umpk-snap-il-mid-scan-part = его программа IL сохранена посреди сканирования ({ $part })
umpk-snap-il-mid-scan = его программа IL сохранена посреди сканирования

## The simulated UMPK's flash file and its server (umpk::sim::state, umpk::sim::serve)

umpk-state-cannot-encode = не удаётся закодировать состояние УМПК
umpk-state-cannot-read = не удаётся прочитать { $file }
umpk-state-bad-file = { $file } — не файл состояния УМПК: { $reason }
umpk-state-hint-remove = удалите его, чтобы начать с пустой flash-памятью
umpk-state-other-model = в { $file } flash-память { $saved }, а не { $model }
umpk-state-hint-other-file = используйте для этой модели другой файл состояния
umpk-state-info-size = информация о программе или история ошибок неверного размера
umpk-serve-read-failed = чтение линии УМПК не удалось
umpk-serve-binary = симулятор УМПК: записана двоичная программа; { $note }
umpk-serve-write-failed = запись в линию УМПК не удалась
umpk-serve-not-model = `{ $model }` — не модель УМПК ({ $models })
umpk-serve-cannot-read-program = не удаётся прочитать программу УМПК { $file }: { $reason }
umpk-serve-line-stopped = линия УМПК остановилась, не успев стать готовой

## The simulated UMPK (umpk::sim)

# What the simulator says when a binary is programmed into it.
umpk-sim-binary-not-executed = симулятор сохраняет и проверяет записанную двоичную программу, но не выполняет её (машинный код УМПК не опубликован): после сброса слово состояния показывает режим «Работа» (программа загружена), а выходы остаются выключенными; чтобы симулятор выполнял логику, загрузите программу IL (`sim program load FILE.il`, `sim serve --umpk-program FILE.il`; docs/il.md)
umpk-sim-page-past-end = страница flash-памяти { $page } вне памяти программ { $model }: страницы 0–{ $last } ({ $bytes } байт, страницы по { $size } байта)
umpk-sim-hint-page = укажите страницу от 0 до { $last } или `off`
umpk-sim-program-kind = { $kind ->
    [none] нет
   *[binary] двоичная программа (сохранена и проверена, не выполняется)
    }
umpk-sim-program-logic = { $program } (выполняется каждый цикл)
# The status word's flags in words (`umpk info`; UMPK manual §4.1.4).
umpk-status-flag = { $flag ->
    [W] W режим «Работа»
    [H] H история ошибок не пуста
    [R] R монитор реального времени включён
    [E] E эхо выключено
    [P] P режим «Программирование»
   *[T] T фаза мигания светодиода
    }

## IL programs on the simulated UMPK (umpk::sim::program, umpk::sim::logic; UMPK manual §3.5)

umpk-il-range = `{ $text }` — диапазон; операнд программы — один бит
umpk-il-elements = { $text }: таймеры и счетчики УМПК — это его собственные инструкции
umpk-il-hint-elements = задержка включения: TIMER T0, GROUP, STEPS (например, TIMER T0, 1, 20 — 2,0 с); деление на N: DIVIDE C0, 4[, I1]
umpk-il-cannot-assign = { $text }: программа не может присваивать { $operand } ({ $meaning })
umpk-il-hint-assign = программа присваивает выходы Q и маркеры M; таймеры и счетчики меняются через TIMER и DIVIDE
umpk-il-user-error = { $text }: код ошибки пользователя — 1–127 (128–255 — системные)
umpk-il-hint-user-error = например, LD I7 / ERROR 12: ошибка 12 в истории, когда включается I7
umpk-il-first-operand = { $text }: первый операнд должен быть { $what ->
        [timer] таймером T0…
       *[counter] счетчиком C0…
    }
umpk-il-delay-group = { $text }: группа задержки — 0 (10 мс), 1 (0,1 с) или 2 (1 с)
umpk-il-delay-steps = { $text }: задержка — 1–255 шагов своей группы
umpk-il-ratio = { $text }: коэффициент деления — 1–255
umpk-logic-no-timer = таймера T{ $n } нет
umpk-logic-delay = T{ $n }: задержка — 1–255 шагов
umpk-logic-no-counter = счетчика C{ $n } нет
umpk-logic-ratio = C{ $n }: коэффициент деления — 1–255
umpk-logic-cannot-assign = { $operand }: программа не может присваивать операнды { $area }

## FX driver: the programming port and the computer link (fx::driver; the FX protocol notes, seed 004)

# What a request was, inside the messages below (`no reply to … on COM6`).
fx-req-port = { $kind ->
    [read] чтение
    [e00] чтение E00
    [write] запись
   *[e10] запись E10
    } { $count } байт по адресу { $address }H
fx-req-port-operand = { $kind ->
    [write] запись
   *[e10] запись E10
    } { $operand }
fx-req-link-read = { $cmd } { $count } точек с { $device }
fx-req-link-bw = BW { $count } точек с { $device }
fx-req-link-ww = WW { $count } значений с { $device }
fx-req-link-wt = WT { $count } значений
# What one attempt got, in the list of attempts.
fx-got = { $got ->
    [data] данные
    [bad-sum] ошибка суммы
    [other] другой ответ
    [noise] помехи
    [partial] неполный ответ
   *[silence] тишина
    }
fx-attempts = { $n ->
    [one] { $n } попытка
    [few] { $n } попытки
   *[many] { $n } попыток
    }
fx-attempts-list = { $n ->
    [one] { $n } попытка
    [few] { $n } попытки
   *[many] { $n } попыток
    }: { $list }
fx-late = ; ещё { $count } символов пришли позже и отброшены (запоздавший ответ никогда не принимается за ответ на следующий запрос)
# The parts of a timeout: where its milliseconds come from.
fx-timeout-given = { $time } (timeout={ $given })
fx-timeout-wire = { $count } символов при { $serial }: { $ms } мс на линии
fx-timeout-wait = ожидание сообщения { $ms } мс
fx-timeout-plc = { $ms } мс на ответ ПЛК
fx-timeout-server = { $ms } мс на сервер устройств
fx-timeout-total = { $ms } мс ({ $parts })
fx-not-quiet = линия { $line } не затихла перед { $what }: за { $ms } мс пришло символов: { $count }
fx-hint-not-quiet-port = с портом программирования может работать только одна программа: закройте GX Developer, панель оператора или терминал на нём; проверьте кабель на помехи
fx-hint-not-quiet-link = plcsh должен быть единственным ведущим на линии компьютерной связи: остановите другие программы, опрашивающие её; проверьте кабель на помехи и терминатор RS-485
fx-no-reply = нет ответа на { $what } на { $line } за { $timeout }{ $late }
fx-no-reply-station = нет ответа на { $what } (станция { $station }) на { $line } за { $timeout }{ $late }
fx-no-reply-no-enq = нет ответа на { $what } (отправлено без ENQ: на ENQ ответа тоже не было) на { $line } за { $timeout }{ $late }
fx-nak-code = { $who ->
    [plc] ПЛК ответил
   *[station] станция { $station } ответила
    } NAK { $code }H на { $what } на { $line }: { $meaning }
fx-hint-nak-area = проверьте операнд по модели (`help OPERAND`)
fx-hint-nak-pc = номер PC у FX — FF (pc=FF)
fx-hint-nak-sum = проверьте настройку суммы (sum=, D8120) и помехи на линии
fx-hint-nak-other = проверьте настройки компьютерной связи ПЛК (D8120, D8121)
fx-nak = ПЛК ответил NAK на { $what } на { $line } ({ $tries }): он отвергает кадр с неверной суммой или адресом, где у него нет устройства
fx-hint-nak-extended = проверьте операнд по модели (`help OPERAND`) и помехи на линии; ПЛК без E-команд (E00/E10/E7/E8) отвечает на них NAK: откройте его как model=FX2N
fx-hint-nak-classic = проверьте операнд по модели (`help OPERAND`) и помехи на линии
fx-bad-reply = неверный ответ на { $what } на { $line } ({ $tries }): { $reason }
fx-hint-bad-sum-port = помехи на линии или неверная скорость/четность (порт работает в 7E1)
fx-hint-bad-sum-link = помехи на линии или скорость либо формат символов, отличные от настроек ПЛК (D8120)
fx-noise = помехи на линии { $line } вместо ответа на { $what } ({ $tries }): { $bytes } — символы, с которых не может начинаться ответ (00H последовательный порт выдаёт за символ с ошибкой четности или кадра)
fx-hint-noise = проверьте экран и заземление кабеля, питание преобразователя и терминатор RS-422/485, а также что ПЛК работает на { $serial } (другая скорость или формат тоже выглядят как помехи)
fx-incomplete = неполный ответ на { $what } на { $line } за { $timeout } ({ $tries }): пришло только { $bytes }
fx-hint-incomplete = проверьте скорость передачи данных ({ $serial }) или увеличьте тайм-аут (timeout= в URL)
fx-other-reply = { $who ->
    [plc] ПЛК ответил
   *[station] станция { $station } ответила
    } на { $what } на { $line } что-то другое ({ $tries }): { $reason }
fx-hint-other-port = с портом программирования может работать только одна программа: закройте GX Developer, панель оператора или терминал на нём
fx-hint-other-link = проверьте, что никакая другая станция не настроена как станция { $station } (D8121) и что никакая другая программа не опрашивает эту линию; ответ, пришедший после тайм-аута, относится к более раннему запросу (увеличьте timeout=)
fx-no-usable-reply = нет пригодного ответа на { $what } на { $line } ({ $tries })
fx-hint-late = ПЛК отвечает позже, чем через { $time }: увеличьте тайм-аут (timeout={ $twice } в URL) или проверьте его время сканирования (D8012)
fx-hint-silent-port = проверьте кабель, что это порт программирования и что он работает на { $serial }
fx-hint-silent-link = проверьте станцию { $station } (D8121 ПЛК), номер PC FF, скорость и формат (D8120) и настройку суммы
fx-read-only = { $operand } ({ $meaning }) установить нельзя
fx-special-device = специальное устройство
fx-driven-by-plc = { $operand } — { $meaning } — управляется ПЛК: запись была бы проигнорирована
fx-hint-run-stop = RUN/STOP — это переключатель ПЛК: на симуляторе `sim cpu stop` / `sim cpu run`
fx-hint-driven = ПЛК устанавливает его каждое сканирование; читайте его, а для своих флагов используйте обычные M или D
fx-retries = retries `{ $value }` должно быть 0–10
fx-no-option = у устройств fx нет параметра `{ $key }`
fx-hint-options = параметры: timeout, retries
# What a reply was instead of the one asked for (fx::driver::computer_link, programming_port).
fx-reply-other-length = кадр данных с { $got } символами данных, а запрошено { $want } (ответ на другой запрос)
fx-reply-data-not-ack-link = кадр данных ({ $bytes }) вместо ACK: запись выполнена, только когда станция отвечает ACK
fx-reply-data-not-ack = кадр данных ({ $bytes }) вместо ACK
fx-reply-ack-not-data = ACK вместо данных
fx-reply-sum = сумма { $got }, а символы дают в сумме { $want }
fx-reply-station = ответ от станции { $station } (номер PC { $pc }), а должна отвечать станция { $want } (номер PC { $wantpc })
fx-reply-garbled = искажённый кадр ({ $bytes }): { $reason }
fx-bad-bits-reply = неверный ответ на { $what }: ожидалось { $count } символов 0/1
fx-bad-words-reply = неверный ответ на { $what }: ожидалось { $count } шестнадцатеричных значений
fx-param-out-of-range = `{ $key }={ $value }` в { $url } вне диапазона
fx-hint-param = { $key ->
    [station] номера станций — 0–31
    [wait] ожидание — 0–15 (×10 мс, 0–150 мс)
   *[pc] номер PC — две шестнадцатеричные цифры, FF для FX
    }
fx-sum-param = `sum={ $value }` в { $url } — не 0 и не 1
fx-format-param = `format={ $value }` в { $url }: поддерживаются форматы 1 и 4
fx-xy-param = `xy={ $value }` в { $url }: octal или decimal
fx-line-params = { $url }: bits=7|8, parity=e|o|n, stop=1|2, baud больше 0
fx-enq-nak = ПЛК ответил NAK на ENQ { $count } раз на { $line }
fx-hint-enq-nak = возможно, с портом программирования работает другая программа
fx-past-table = за пределами таблицы адресов
fx-baud-zero = `baud=0` в { $url }: скорость передачи данных должна быть больше нуля
fx-sim-other-model = симулируемый ПЛК `{ $name }` — { $model }, а не { $want }
fx-cannot-read-program = { $url }: не удаётся прочитать { $file }: { $reason }
fx-protocol-param = `protocol={ $value }` в { $url }: port или link

## FX operands (fx::operand, fx::space; the FX protocol notes, seed 004)

# What a device area holds (`help`, completion, messages).
fx-area-meaning = { $area ->
    [X] вход
    [Y] выход
    [M] вспомогательное реле
    [S] реле состояния
    [TS] контакт таймера
    [TC] катушка таймера (управляется программой; только для чтения)
    [CS] контакт счетчика
    [CC] катушка счетчика (управляется программой; только для чтения)
    [TN] текущее значение таймера
    [CN] текущее значение счетчика (CN200–CN255 — 32-битные)
   *[D] регистр данных
    }
# Special devices (FX programming manual, special device lists).
fx-special-meaning = { $device ->
    [M8000] монитор RUN (включён, пока ПЛК работает)
    [M8001] монитор RUN, инверсный (выключен, пока ПЛК работает)
    [M8002] начальный импульс (включён в первом сканировании после RUN)
    [M8003] начальный импульс, инверсный (выключен в первом сканировании после RUN)
    [M8011] тактовый импульс 10 мс (5 мс вкл., 5 мс выкл.)
    [M8012] тактовый импульс 100 мс (50 мс вкл., 50 мс выкл.)
    [M8013] тактовый импульс 1 с (0,5 с вкл., 0,5 с выкл.)
    [M8014] тактовый импульс 1 мин (30 с вкл., 30 с выкл.)
    [D8000] время сторожевого таймера, мс
    [D8010] текущее время сканирования, 0,1 мс
    [D8011] минимальное время сканирования, 0,1 мс
    [D8012] максимальное время сканирования, 0,1 мс
    [D8120] формат связи (компьютерная связь: скорость, четность, сумма …)
   *[D8121] номер станции компьютерной связи
    }
fx-range-kind = для диапазона нужны два операнда одного вида и размера: { $first }..{ $last }
fx-range-reversed = конец диапазона { $last } раньше его начала { $first }
fx-range-steps = { $last } не отстоит от { $first } на целое число шагов по { $step }
fx-range-long = диапазон длиннее { $max } операндов
fx-number-missing = в `{ $text }` после { $area } нужен номер устройства
fx-not-digit = `{ $char }` в `{ $text }` — не цифра
fx-number-long = номер устройства `{ $digits }` слишком длинный
fx-not-octal = номера { $area } восьмеричные ({ $area }0–{ $area }7, { $area }10–{ $area }17 …): `{ $char }` в `{ $text }` — не восьмеричная цифра
fx-number-large-octal = `{ $digits }` слишком велико: номера устройств — до 177777 (восьмеричное)
fx-number-large = `{ $digits }` слишком велико: номера устройств — до { $max }
fx-operand-missing = не хватает операнда
fx-unknown-type = неизвестный тип `{ $name }` (используйте WORD, INT, DWORD, DINT, REAL)
fx-group-digits = K{ $n }: в группе 1–8 тетрад по 4 бита (K1 … K8)
fx-unknown-device = неизвестное устройство FX `{ $text }`
fx-hint-devices = устройства: X Y M S (биты), T C или TS CS (контакты таймеров/счетчиков), TC CC (катушки), TN CN D (слова), KnX KnY KnM KnS (группы)
fx-group-area = K{ $n }{ $area }: группы составляются из битов X, Y, M или S
fx-view = { $operand } нельзя читать как { $dtype }
fx-hint-view = D принимает /WORD, /INT, /DWORD, /DINT, /REAL (32 бита: D и следующий D); группы K1–K4 — /INT, /WORD, /DINT, /DWORD; группы K5–K8 — /DINT, /DWORD (K8 также /REAL)

fx-not-on-model = { $operand } нет у { $model } ({ $range })
fx-crosses-special = { $operand } переходит из обычных устройств в специальные
fx-hint-e-commands = у FX3U до него доходят E-команды (откройте с model=FX3U); у { $model } — только компьютерная связь (fxlink:, с платой FX-485 и настроенным D8120)
fx-past-port-table = { $operand } вне таблицы адресов порта программирования { $model } ({ $commands }; она охватывает { $reach })
fx-not-on-link = { $operand } ({ $meaning }) недоступен через компьютерную связь
fx-hint-not-on-link = читайте вместо него контакт (TS/CS) или используйте порт программирования (fx:)
fx-describe-group = { $bits }-битная группа битов «{ $meaning }» { $first }–{ $last }
fx-describe-pair = 32-битное значение в D{ $low } (младшее) и D{ $high } (старшее)
fx-describe-special = специальный { $meaning }
fx-describe-unaligned = {" "}— внимание: группа начинается с { $first }; руководство советует номер, оканчивающийся на 0 ({ $area }0, { $area }10 …)
fx-complete-group = { $bits }-битная группа битов «{ $meaning }»

## Kinco servo driver (servo::driver, servo::frame; Kinco servo RS232 notes, seed 002)

# The manual's three reasons a drive stays silent (§2.4).
servo-silence-causes = привод Kinco не отвечает, если (1) неверный ID привода, (2) объект не существует, (3) неверная контрольная сумма (руководство, §2.4)
servo-port-still-gone = последовательный порт { $port } по-прежнему отсутствует
servo-port-gone = последовательный порт { $port } пропал
servo-port-io = ошибка ввода-вывода на последовательном порту { $port }
servo-hint-port-gone = возможно, USB-адаптер отключён или сервер порта перезапущен: проверьте кабель и адаптер (`plcsh ports` показывает имеющиеся порты); следующая команда снова откроет порт, когда он вернётся
servo-no-echo = нет эха запроса на { $port } (включён режим петли)
servo-hint-no-echo = петля разомкнута (кабель) или линия не в режиме петли: уберите echo=1 из URL
servo-reply-before-echo = на { $port } ожидалось эхо запроса (echo=1), но первым пришёл ответ привода: { $bytes }; линия не в режиме петли
servo-hint-reply-before-echo = подключитесь с echo=0 (или включите режим петли привода, панель d5.15 = 1)
servo-echo-differs = эхо отличается от запроса на { $port }: отправлено { $sent }, вернулось { $echo }; вероятная причина: неверная контрольная сумма — привод игнорирует искажённый кадр
servo-hint-baud-wiring = проверьте скорость передачи данных (по умолчанию у привода 38400, панель d5.02) и подключение
servo-reply-is-request = ответом на { $verb ->
        [read] чтение
        [write] запись
       *[request] запрос
    } { $object } пришёл сам запрос: линия возвращает запросы эхом (режим петли RS232)
servo-hint-use-echo = подключитесь с echo=1, чтобы plcsh пропускал эхо
servo-bad-reply = неверный ответ на { $verb ->
        [read] чтение
        [write] запись
       *[request] запрос
    } { $object }: { $reason }
servo-hint-bad-reply = возможно, на линии работает другой ведущий или привод, либо неверна скорость передачи данных
# No reply: the head and the likely cause in one sentence.
servo-silent = нет ответа от привода с ID { $id } на { $verb ->
        [read] чтение
        [write] запись
       *[request] запрос
    } { $object } за { $timeout }; вероятная причина: { $cause ->
        [function] неизвестный код функции { $code } — привод отвечает только на чтение (40) и запись (23, 2B, 2F) и игнорирует всё остальное
        [checksum] неверная контрольная сумма — кадр оканчивается на { $got }, а для байтов перед ней нужна { $want }
        [stray] неверная контрольная сумма — вернулись только случайные байты ({ $count }: { $bytes }), значит, кадры искажаются на линии (скорость или подключение)
        [object] неизвестный объект — привод с ID { $id } отвечает на чтение слова состояния, значит, { $object } на этом приводе, вероятно, не существует
        [stopped] привод перестал отвечать — ID { $id } отвечал раньше; проверьте питание и кабель
       *[id] неверный ID — на ID { $id } никто не отвечает (заводской ID 1, панель d5.01; проверьте также питание, кабель и скорость)
    }
servo-silent-late = нет ответа от привода с ID { $id } на { $verb ->
        [read] чтение
        [write] запись
       *[request] запрос
    } { $object } за { $timeout }; вероятная причина: запоздавшие ответы — { $what }
servo-late-stale = вместо него пришёл ответ на другой запрос ({ $frames })
servo-late-bytes = после тайм-аута пришли и отброшены байты: { $count }
servo-hint-late = привод отвечает позже тайм-аута: увеличьте его (timeout= в URL, сейчас { $timeout }) и проверьте, что на линии нет другого ведущего; запоздавший ответ никогда не принимается за ответ на следующий запрос
servo-refused = привод с ID { $id } отказал в { $verb ->
        [read] чтении
        [write] записи
       *[request] запросе
    } { $object }: код прерывания 16#{ $code } — { $meaning }
servo-resolution-zero = привод сообщает разрешение энкодера 0 (6410.03)
servo-no-option = у устройств servo нет параметра `{ $key }`
servo-hint-options = параметры: encoder, timeout
servo-flag-param = `{ $key }={ $value }` в { $url } — не 0 и не 1
servo-baud-zero = `baud=0` в { $url }: скорость передачи данных должна быть больше нуля
servo-latency-param = `latency={ $value }` в { $url } — не длительность (например, 1ms)
servo-ids-in-url = { $message } в { $url }
servo-not-ids = `{ $list }` — не список ID приводов (0–255), например 1,2
# What is wrong with a reply frame (servo::frame).
servo-frame-checksum = неверная контрольная сумма { $got } (байты перед ней дают контрольную сумму { $want })
servo-frame-reply-checksum = в ответе неверная контрольная сумма { $got } (байты перед ней дают контрольную сумму { $want })
servo-frame-id = ответ от привода с ID { $got }, ожидался ID { $want }
servo-frame-object = ответ относится к объекту { $got }, ожидался { $want }
servo-frame-func = код функции ответа { $got } не отвечает на запрос { $request }
servo-frame-echo = подтверждение записи возвращает данные { $got }, а в запросе было { $want }
# CANopen abort codes the drive answers with (function code 80).
servo-abort = { $code ->
    [x05040001] недопустимая команда
    [x06010001] попытка чтения объекта только для записи
    [x06010002] попытка записи объекта только для чтения
    [x06020000] объекта нет в словаре объектов
    [x06040041] объект нельзя отобразить
    [x06070010] тип данных не совпадает, длина параметра службы не совпадает
    [x06070012] тип данных не совпадает, длина параметра службы слишком велика
    [x06090030] значение параметра вне диапазона
   *[other] неизвестный код прерывания
    }

## The simulated Kinco drive's faults and switches (servo::sim::control, servo::sim::faults; `servo sim …`)

servo-sim-not-number = `{ $text }` — не число
servo-sim-id-range = ID привода — 0-255
servo-sim-unknown-option = неизвестный параметр `{ $key }`
servo-sim-count = count — 1 или больше, либо all
servo-sim-all-and-count = укажите `all` или count=N, но не оба
servo-sim-fault-extra = неожиданное `{ $word }` после `fault { $kind }`: укажите all или count=N
servo-sim-fault-duration = fault { $kind } нужна одна длительность, например fault { $kind } 50ms
servo-sim-fault-abort = fault abort нужны объект и код прерывания, например fault abort target_position 16#06090030
servo-sim-abort-bits = код прерывания — 32 бита
servo-sim-pulses-freq = pulses нужен freq=HZ
servo-sim-pulses-count = pulses нужен count=N
servo-sim-not-freq = `{ $text }` — не частота в Гц
servo-sim-pulse-count = count — 0 или больше
servo-sim-not-dir = `dir={ $dir }` — не fwd и не rev
servo-sim-unknown-word = неизвестная команда `servo sim { $word }`
servo-sim-fault-bits = код неисправности — 16 бит
servo-sim-no-drive = нет симулируемого привода с ID { $id } (ID: { $ids })
servo-sim-several-drives = на линии несколько приводов ({ $ids }): укажите нужный через id=N
servo-sim-fault-injected = привод с ID { $id }: внесена неисправность 16#{ $code }
servo-sim-fault-armed = привод с ID { $id }: неисправность 16#{ $code } взведена на положении { $position } inc
servo-sim-fault-acted = { $time }s  привод с ID { $id }: неисправность 16#{ $code } на положении { $position } inc (сработала взведённая неисправность)
servo-sim-no-fault-acted = ни одна взведённая неисправность не сработала
servo-sim-line-fault = { $scope ->
        [all] все приводы
       *[one] привод с ID { $id }
    }: { $fault }; действует на { $count ->
        [one] следующий запрос
        [every] каждый запрос до `servo sim fault clear`
       *[many] { $n ->
            [one] следующий { $n } запрос
            [few] следующие { $n } запроса
           *[many] следующие { $n } запросов
        }
    }
servo-sim-faults-cleared = неисправности линии сняты
servo-sim-switch = привод с ID { $id }: { $switch ->
        [home] датчик исходного положения
        [neg] концевой выключатель отрицательного направления
       *[pos] концевой выключатель положительного направления
    } { $position ->
        [off] выключен
       *[at] на { $at } inc
    }
servo-sim-pulses = привод с ID { $id }: { $count } импульсов с частотой { $freq } Гц { $dir ->
        [reverse] в обратном направлении
       *[forward] в прямом направлении
    } с t={ $start } с до t={ $end } с
servo-sim-strict = размеры записи: { $strict ->
        [on] размер должен совпадать с объектом (иначе 0x06070010)
       *[off] нестрогие размеры
    }
# A line fault in words (`servo sim fault …`, `faults`).
servo-sim-fault-kind = { $kind ->
    [no-reply] нет ответа
    [bad-checksum] неверная контрольная сумма в ответе
    [delay] ответ задерживается на { $ms } мс
    [abort] прерывание 16#{ $code } ({ $meaning }) для { $object }
   *[drop-echo] эхо пропущено
    }

## FX frames (fx::link, fx::port; the FX protocol notes, seed 004)

# What is wrong with a frame (inside `a garbled frame (…): …`).
fx-malformed = { $what ->
    [no-crlf] нет CR LF после ответа
    [too-short] слишком короткий
    [station-not-hex] номер станции или PC — не шестнадцатеричный
    [code-not-hex] код ошибки — не шестнадцатеричный
    [length-after-etx] неверная длина после ETX
    [sum-not-hex] сумма — не шестнадцатеричная
    [bytes-after-etx] байты после ETX
    [unknown-command] неизвестная команда или неверная длина
    [address-not-hex] адрес — не шестнадцатеричный
    [count-not-hex] количество — не шестнадцатеричное
    [data-length] длина данных не совпадает с количеством
    [data-not-hex] данные — не шестнадцатеричные
   *[not-read-reply] не STX данные ETX сумма запрошенной длины
    }
# The computer link's NAK error codes (seed 004: "若发送码有误，则有以下回应").
fx-nak-meaning = { $code ->
    [c02] ошибка суммы (сумма в запросе не совпадает с его символами)
    [c03] ошибка протокола (запрос не соответствует процедуре управления)
    [c06] ошибка области символов (неизвестная команда либо номер или количество устройств, которых у ПЛК нет)
    [c07] ошибка символа (данные для записи — не шестнадцатеричный ASCII)
    [c0A] ошибка номера PC (нет станции с таким номером PC)
    [c18] ошибка удалённого управления (RUN/STOP нельзя переключить удалённо)
   *[other] неизвестный код ошибки
    }

## The simulated FX PLC's control words, snapshots and server (fx::control, fx::snapshot, fx::sim)

fx-sim-not-x = `{ $text }` — не вход X (X0, X17 …)
fx-sim-no-such-input = { $operand } — не вход { $model } (X0–X{ $last })
fx-sim-input-usage = input нужны вход и уровень: input X0=1
fx-sim-input-extra = `{ $word }` после input { $input } не понято
fx-sim-input-level = `{ $input }`: напишите input { $input }=1 или =0
fx-sim-inputs-none = ни один вход X не включён
fx-sim-inputs-on = включены: { $inputs }
fx-sim-not-word = `{ $word }` — не управляющее слово симулятора ПЛК FX
fx-snap-other-model = снимок сделан с { $saved }, а этот симулятор — { $model }
fx-snap-image = сохранённый образ устройств не подходит к этой модели
fx-serve-cannot-read = не удаётся прочитать { $file }: { $reason }
fx-serve-stopped = порт FX остановился, не успев стать готовым

## The simulated drive's homing and pulse input (servo::sim)

servo-sim-homing-neg = методу 17 нужен концевой выключатель отрицательного направления
servo-sim-homing-pos = методу 18 нужен концевой выключатель положительного направления
servo-sim-homing-method = метод возврата в исходное положение { $method } не симулируется (методы { $methods })
servo-sim-no-drive-id = на симулируемой линии нет привода с ID { $id }
servo-sim-pulse-ab = импульсный вход привода настроен на A/B (2508.03 = 2); импульсный выход ПЛК — импульс + направление: сначала установите 2508.03 в 1
servo-sim-no-drive-short = нет привода с ID { $id }
servo-not-servo-any-more = устройство больше не отвечает как сервопривод

## Links: control channels, shared lines, RFC 2217, pseudo-terminals (core::link)

link-cannot-open-channel = не удаётся открыть { $what } по пути { $path }
link-hint-channel-path = выберите другой путь или удалите старый файл, оставшийся от завершённого сервера
link-control-line-long = управляющая строка — не больше { $max } байт
link-control-line-utf8 = управляющая строка должна быть текстом UTF-8
link-cannot-reach-channel = нет связи с управляющим каналом симулятора { $path }
link-hint-reach-channel = `plcsh sim serve` ещё работает? Путь управляющего канала указан в его строке готовности
link-channel-answered = управляющий канал ответил `{ $reply }`
link-simulator-refused = симулятор отказал
# The names of the simulators' control channels (inside link-cannot-open-channel).
link-channel-name = { $device ->
    [servo] управляющий сокет сервопривода
    [umpk] управляющий канал обслуживаемого УМПК
   *[fx] управляющий канал обслуживаемого ПЛК FX
    }
link-line-settings = { $line } уже открыта с { $open }, а не { $settings }
link-hint-line-settings = все приводы на одной линии используют одну скорость передачи данных и одну настройку петли
link-pipe-closed = другой конец канала закрыт
link-no-reply-timeout = нет ответа за время тайм-аута
link-rfc2217 = сервер RFC 2217 по адресу { $addr } { $what ->
        [confirm] не подтвердил настройки линии вовремя
        [agree] не согласился вовремя на настройку последовательного порта (COM-PORT-OPTION)
        [closed] закрыл соединение ({ $reason })
        [refused] не разрешил этой стороне настраивать последовательный порт
       *[baud] установил { $got } бод вместо { $want }
    }
link-hint-rfc2217 = проверьте, что канал сервера устройств работает в режиме RFC 2217 (или используйте +tcp:// для канала raw TCP) и поддерживает эту скорость и формат
link-pty-dup-master = не удаётся дублировать ведущую сторону псевдотерминала
link-pty-dup-slave = не удаётся дублировать ведомую сторону псевдотерминала
link-pty-register = не удаётся зарегистрировать ведущую сторону псевдотерминала в tokio
link-pty-open = не удаётся открыть псевдотерминал
link-pty-call = { $call } на псевдотерминале
link-pty-nonblocking = не удаётся перевести псевдотерминал в неблокирующий режим
link-not-symlink = { $path } существует и не является символической ссылкой; выберите другой путь
link-cannot-symlink = не удаётся создать символическую ссылку { $path }
link-control-no-port = в управляющем файле нет номера порта
link-windows-no-pty = в Windows нет псевдотерминалов для работы симулятора
link-hint-windows-tcp = запустите его на порту TCP (sim serve --rtu-tcp 0, --servo-tcp 0, --fx-tcp 0, --fx-link-tcp 0, --umpk-tcp 0) и подключайтесь через rtu+tcp://, kinco+tcp://, fx+tcp://, fxlink+tcp:// или umpk+tcp://

# `help OPERAND` on an FX (fx::space).
fx-help-group-range = 0…{ $max } (недостающие старшие биты — нули)
fx-help-port = порт программирования ({ $commands }): байтовый адрес { $address }H, байт: { $bytes }
fx-help-force = , адрес принудительной установки { $address }H
fx-help-link = компьютерная связь: устройство { $device }
fx-help-manual = руководство: seed 004 (группы устройств FX KnX, протокол порта программирования; fx-and-masterk.md A, B)
fx-help-type = тип { $dtype } ({ $bits } бит), диапазон { $range }
fx-help-on-model = у { $model }: { $range }

# The two ways to an FX (fx::space::Proto).
fx-proto = { $proto ->
    [port] порт программирования
   *[link] компьютерная связь
    }
