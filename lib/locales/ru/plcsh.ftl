# Сообщения plcsh на русском языке. Термины — по глоссарию (shared/spec/glossary.md): как их пишут
# руководства K2 и УМПК. Операнды, мнемоники, команды, ключи и поля JSON не переводятся.

## Вид ошибки (core::error, output)

label-hint = подсказка: { $hint }
label-warning = Внимание: { $warning }
label-note = примечание: { $note }

error-kind-cause = { $kind ->
    [syntax] строка не разбирается: лишний символ, незакрытая кавычка, нет `=` в `set`
    [operand] операнд неизвестен или записан неверно (`VX0`, `M0.8`, `SMB`)
    [value] значение не помещается в операнд (`set VB2=300`) или не является числом в нужных единицах
    [range] операнд за концом области памяти модели, или у модели нет такой области (`AIW0` на K205-16DT)
    [unsupported] это устройство или линия связи так не умеет: SM, T и C по обычному Modbus, инструкция без программы-помощника
    [refused] устройство ответило отказом: исключение Modbus, код отказа сервопривода, результат программы-помощника
    [link] нет ответа, тайм-аут, неверная контрольная сумма (CRC), разорванное соединение, порт не открывается
    [timeout] ожидание не дождалось (`wait`, команда программе-помощнику не подтверждена)
    [usage] команда использована неверно: нет аргумента, неизвестная команда или устройство, файл занят
    [script] сценарий Lua завершился с ошибкой: ошибка выполнения, не выполнен `plcsh.assert_eq`, `os.exit`
    [io] ошибка файла или операционной системы: файл не читается или не записывается
    [interrupted] команду остановили Ctrl-C, SIGTERM или SIGHUP; обработчики прерывания выполнены
   *[state] устройство в состоянии, в котором команда не выполняется: PTO занят, почтовый ящик программы-помощника занят, программа-помощник остановлена
}
error-kind-fix = { $kind ->
    [syntax] знак ^ под строкой указывает на слово; `help COMMAND` показывает форму команды
    [operand] `help VW100` объясняет операнд; Tab дополняет операнды
    [value] в сообщении указан диапазон типа операнда; для значений со знаком используйте вид (`VW0/INT`)
    [range] сверьте `model=` в URL с ПЛК (`plcsh models`); подсказка называет модели, у которых эта область есть
    [unsupported] установите программу-помощник для регистров SM и инструкций (docs/agent.md) или используйте симулятор
    [refused] подсказка говорит, какой отказ; при `illegal data address` сверьте `model=` с ПЛК
    [link] проверьте по списку «нет ответа»: unit id, baud/parity/stop, подключение A/B, права доступа, программу, занявшую порт; `-v` показывает пакеты
    [timeout] дайте ожиданию больше времени или проверьте, что ПЛК в режиме RUN и программа-помощник вызывается в каждом цикле сканирования
    [usage] `help COMMAND`; `devices` перечисляет имена устройств
    [script] сообщение называет файл:строку и показывает трассировку
    [io] сообщение называет файл и причину, названную системой
    [interrupted] запустите снова; код завершения говорит, какой сигнал (docs/reference/exit-status.md)
   *[state] дождитесь окончания текущей операции (`pto 0 status`) или переведите ПЛК в режим RUN
}

lang-unknown = неизвестный язык `{ $lang }`: plcsh говорит на en, ru, zh-CN

## Значения (core::literal): литералы IEC 61131-3 и проверка, помещаются ли они в операнд

literal-missing = не указано значение
literal-space = лишний пробел в значении `{ $value }`
literal-duration = { $message }
literal-typed-integer = { $prefix }# принимает целое число; для числа с плавающей точкой напишите REAL#{ $rest }
literal-unknown-prefix = неизвестный префикс типа `{ $prefix }#` (используйте B#, W#, DW#, INT#, DI#, REAL#, T# или основание 2#, 8#, 16#)
literal-number-missing = не указано число
literal-c-notation = `{ $typed }` — запись языка C; напишите { $iec } (IEC 61131-3, как в KincoBuilder)
literal-unknown-radix = основание { $radix }# не из числа 2#, 8#, 10#, 16#
literal-no-digits = нет цифр после { $radix }#
literal-not-digit-of-base = `{ $char }` не цифра в системе по основанию { $radix }
literal-too-wide = { $value } шире 32 бит (не больше 16#FFFF_FFFF)
literal-not-number = `{ $value }` не число
literal-not-digit = `{ $char }` не цифра в `{ $value }`
literal-too-large = { $value } слишком велико: целые числа — до { $max }
value-does-not-fit = { $value } не помещается в { $dtype } ({ $min }…{ $max })
value-not-bit = { $value } не помещается в бит (используйте 0/1, TRUE/FALSE, ON/OFF)
value-bit-not-real = { $value } — бит, а не REAL
value-not-real = { $value } не помещается в REAL (32-битное число IEEE с плавающей точкой: не больше ±{ $max })
value-not-integer = { $value } не целое число; { $dtype } хранит целые числа (чтобы записать число IEEE с плавающей точкой, возьмите 32-битный операнд с /REAL, например VD100/REAL)
value-type-too-wide = { $value } — это { $dtype } ({ $bits } бит), он не помещается в { $width }-битный операнд
value-out-of-range = { $value } вне диапазона { $dtype } (0…{ $max })
value-out-of-range-group = { $value } вне диапазона { $bits }-битной группы (0…{ $max })
value-out-of-range-signed = { $value } вне диапазона { $dtype } (0…{ $max }); напишите { $signed }#{ $number }, чтобы записать его дополнительный код
value-out-of-range-group-signed = { $value } вне диапазона { $bits }-битной группы (0…{ $max }); напишите { $signed }#{ $number }, чтобы записать его дополнительный код

## Длительности, тайм-ауты и частоты (core::literal)

duration-not-whole-ms = T#{ $value } — не целое число миллисекунд
duration-too-long = `{ $value }` длиннее самой долгой длительности, { $max } мкс (около 292 000 лет)
duration-missing = не указана длительность (например 500ms, 2s, 250us)
duration-not-duration = `{ $value }` не длительность (например 500ms, 2s, 250us)
duration-needs-unit = в `{ $value }` у каждого числа нужна единица (h, m, s, ms, us), например { $number }ms или { $number }s
duration-unknown-unit = неизвестная единица времени `{ $unit }` в `{ $value }` (используйте h, m, s, ms, us)
timeout-not-positive = `timeout={ $value }` должен быть больше нуля (например 200ms)
timeout-too-short = `timeout={ $value }` короче микросекунды, самого короткого ожидания линии связи (например 200ms)
timeout-too-long = `timeout={ $value }` длиннее суток ({ $max } мс), самого долгого ожидания ответа
freq-not-frequency = `{ $value }` не частота (например 2kHz, 500Hz)
freq-unknown-unit = неизвестная единица частоты `{ $unit }` в `{ $value }` (используйте Hz, kHz)
freq-not-positive = `{ $value }` не положительная частота
freq-too-large = `{ $value }` — слишком большая частота (не больше { $max } Hz)

## Выражения операндов: количество и диапазоны (core::operand, k2::operand)

count-missing-bracket = нет `]` в записи с количеством (например { $example })
count-not-a-count = `{ $count }` не количество (например { $example })
count-out-of-range = количество должно быть 1…{ $max }
range-one-dots = в диапазоне одно `..`: ПЕРВЫЙ..ПОСЛЕДНИЙ, например { $example }
range-mixed = диапазону нужны два операнда одной области и одного размера: { $first }..{ $last }
range-group-sizes = диапазону групп битов нужен один размер группы
range-backwards = конец диапазона { $last } раньше его начала { $first }
range-off-step = { $last } не попадает в шаг { $step } от { $first } (диапазон идёт с шагом размера операнда)
range-too-long = диапазон длиннее { $max } операндов
operand-missing = не указан операнд
operand-unknown-type = неизвестный тип `{ $name }` (используйте BOOL, BYTE, SINT, WORD, INT, DWORD, DINT, REAL)
operand-view-width = ширина { $operand } — { $bits } бит; /{ $view } нужно { $need } бит (вид сохраняет ширину: /SINT для байтов, /INT для слов, /DINT или /REAL для двойных слов)
operand-unexpected-after = лишнее `{ $rest }` после { $head }

## Операнды K2 (k2::operand, k2::space; руководство K2 §3.2)

k2-area-meaning = { $area ->
    [I] дискретные входы
    [Q] дискретные выходы
    [M] внутренние биты памяти
    [V] область V (память переменных)
    [SM] область SM (системные и функциональные регистры)
    [AI] аналоговые входы
    [AQ] аналоговые выходы
    [T] таймеры (текущее значение)
   *[C] счетчики (текущее значение)
}
k2-address-too-large = `{ $operand }` за пределами всех областей K2: адреса — не больше { $max } (самая большая область, V, кончается на VB{ $last })
k2-element-needs-number = после { $area } нужен номер ({ $area }0…{ $area }255)
k2-analog-words = аналоговые значения — слова: { $area }W0, { $area }W2 …
k2-analog-needs-address = после { $area }W нужен адрес байта (например { $area }W0)
k2-analog-even = аналоговые слова стоят по чётным адресам: { $below } или { $above }
k2-analog-even-last = аналоговые слова стоят по чётным адресам: { $below }
k2-needs-byte-address = после { $operand } нужен адрес байта
k2-byte-has-no-bit = у байта нет бита; бит записывается как { $bit }
k2-word-has-no-bit = у слова нет бита; бит записывается как { $bit }
k2-needs-bit-or-size = после { $area } нужен бит (`{ $area }0.0`) или буква размера (`{ $area }B0`, `{ $area }W0`, `{ $area }D0`)
k2-byte-needs-bit-or-size = после { $area }{ $byte } нужен бит ({ $area }{ $byte }.0) или размер ({ $area }B{ $byte }, { $area }W{ $byte }, { $area }D{ $byte })
k2-bit-missing = не указан номер бита 0…7
k2-bit-too-large = бита { $bit } нет: биты 0…7 (последний — { $last })
k2-group-size = группы битов — K1…K8 (от 4 до 32 бит)
k2-group-nested = { $group } группирует биты I, Q, M, V или SM; группы не вкладываются друг в друга
k2-group-needs-bit = { $group } группирует биты: напишите { $example } (адрес бита), а не байт или слово
k2-group-area = { $group } группирует биты I, Q, M, V или SM
k2-not-operand-no-area = `{ $operand }` не операнд K2: операнд начинается с буквы области
k2-not-operand-unknown-area = `{ $operand }` не операнд K2: неизвестная область `{ $area }`
k2-hint-did-you-mean = может быть, { $suggestions }? области: I Q M V SM AI AQ T C
k2-hint-no-data-blocks = у K2 нет блоков данных: его память данных — область V (VB0, VW0, VD0 …); области: I Q M V SM AI AQ T C
k2-hint-no-options = здесь команды не принимают -ключей; назовите операнды, например VW0, I0.0, SMB67
k2-hint-areas = области: I Q M V SM AI AQ T C, например VW0, I0.0, Q0.1, SMB67, T5
k2-model-has-no-area = у { $model } нет области { $area } ({ $meaning })
k2-hint-models-with = модели с областью { $area }: { $models }
k2-past-the-end = { $operand } за концом области { $area } на { $model } (последний { $size ->
        [bit] бит
        [byte] байт
        [word] слово
        [dword] двойное слово
        [group] группа
       *[element] элемент
    } — { $last })
k2-area-too-small = { $operand } не помещается в область { $area } на { $model }: в ней { $bits } бит, меньше, чем нужно для { $size ->
        [bit] бита
        [byte] байта
        [word] слова
        [dword] двойного слова
        [group] группы
       *[element] элемента
    }
k2-bit-and-byte-past-the-end = { $operand }: бита { $bit } нет (биты 0…7), а байт { $byte } за концом области { $area } на { $model } (последний бит — { $last })
k2-hint-area-bits = { $meaning } на { $model }: { $first } … { $last }

## Связь: нет ответа, тайм-ауты, порты (core::link, k2::driver)

link-no-reply = устройство не ответило: нет ответа от unit { $unit } за { $timeout }
link-no-valid-reply = unit { $unit } не прислал верного ответа за { $timeout }: { $what }
link-closed = ПЛК закрыл соединение вместо ответа
link-failed = ошибка связи
link-attempts = { $message } ({ $attempts ->
        [one] { $attempts } попытка
        [few] { $attempts } попытки
       *[many] { $attempts } попыток
    })
k2-hint-no-reply = { $link ->
    [tcp] проверьте unit id (unit=), что HOST:PORT — это ПЛК (K204ET отвечает по Modbus TCP на порту 502) и что он включён и доступен (ping)
    [rtu] проверьте unit id (unit= — номер станции порта ПЛК), подключение (RS485 A/B, земля), настройки порта (baud=, parity=, stop=) против настроек порта ПЛК и путь к порту
    [gateway] проверьте unit id (unit=), адрес и порт шлюза и что его настройки последовательного порта (скорость, четность, стоповые биты) совпадают с настройками порта ПЛК
    [rfc2217] проверьте unit id (unit=), адрес и порт сервера устройств и настройки линии (baud=, parity=, stop=) против настроек порта ПЛК
   *[stream] проверьте unit id и что находится на другом конце потока
}
k2-hint-garbled = { $link ->
    [rtu] проверьте настройки порта (baud=, parity=, stop=) против настроек порта ПЛК, подключение (RS485 A/B, земля, терминаторы на обоих концах длинной линии) и что на линии не говорит другой ведущий или другое устройство
    [gateway] проверьте настройки последовательного порта шлюза (скорость, четность, стоповые биты) против настроек порта ПЛК, подключение от шлюза к ПЛК и что шлюз в прозрачном режиме (RTU), а не Modbus TCP
    [rfc2217] проверьте настройки линии (baud=, parity=, stop=) против настроек порта ПЛК и подключение от сервера устройств к ПЛК
    [tcp] проверьте, что HOST:PORT говорит на Modbus TCP (шлюзу RTU нужен rtu+tcp://)
   *[stream] проверьте, что находится на другом конце потока
}
k2-hint-damaged = { $link ->
    [rtu] байты повреждены по дороге; проверьте настройки порта (baud=, parity=, stop=) против настроек порта ПЛК, подключение (RS485 A/B, земля, терминаторы на обоих концах длинной линии) и что на линии не говорит другой ведущий или другое устройство; plcsh повторяет запрос (retries=)
    [gateway] байты повреждены по дороге; проверьте настройки последовательного порта шлюза (скорость, четность, стоповые биты) против настроек порта ПЛК, подключение от шлюза к ПЛК и что шлюз в прозрачном режиме (RTU), а не Modbus TCP; plcsh повторяет запрос (retries=)
    [rfc2217] байты повреждены по дороге; проверьте настройки линии (baud=, parity=, stop=) против настроек порта ПЛК и подключение от сервера устройств к ПЛК; plcsh повторяет запрос (retries=)
    [tcp] байты повреждены по дороге; проверьте, что HOST:PORT говорит на Modbus TCP (шлюзу RTU нужен rtu+tcp://); plcsh повторяет запрос (retries=)
   *[stream] байты повреждены по дороге; проверьте, что находится на другом конце потока; plcsh повторяет запрос (retries=)
}
k2-hint-closed = plcsh переподключается и повторяет запрос (retries=); если это повторяется, проверьте ограничение ПЛК на число соединений Modbus TCP и не перехватывает ли соединение другой клиент или шлюз
link-cannot-connect = не удаётся подключиться к { $addr }
link-name-not-looked-up = не удаётся подключиться к { $addr }: имя не найдено за { $ms } мс
link-hint-name-server = укажите IP-адрес или проверьте сервер имён
link-connect-timeout = не удаётся подключиться к { $addr }: нет ответа за { $ms } мс
link-cannot-listen = не удаётся слушать { $addr }
link-hint-listen = выберите другой порт (0 — любой свободный); для портов ниже 1024 нужны права
link-cannot-open-port = не удаётся открыть последовательный порт { $port }
link-cannot-use-port = не удаётся использовать последовательный порт { $port }
link-hint-open-port = `plcsh ports` перечисляет последовательные порты этого компьютера и их USB-адаптеры; проверьте имя ({ $examples }) и что порт не занят другой программой (KincoBuilder, программой терминала)
link-hint-open-port-group = `plcsh ports` перечисляет последовательные порты этого компьютера и их USB-адаптеры; проверьте имя ({ $examples }), что порт не занят другой программой (KincoBuilder, программой терминала) и что у вас есть право его открыть (группа dialout: sudo usermod -aG dialout $USER, затем войдите в систему заново)
link-not-host-port = `{ $target }` в { $url } не HOST:PORT
link-hint-host-port = укажите адрес сервера устройств и TCP-порт его последовательного канала, например 192.168.127.254:4001
link-no-address = имени не соответствует ни один адрес
link-hint-server = проверьте адрес сервера устройств и TCP-порт этого последовательного канала, что он в режиме сервера raw TCP (или RFC 2217 для +rfc2217://), что канал не занят другим клиентом и что порт не закрыт межсетевым экраном
link-connection-closed = соединение закрыто
link-cannot-start-thread = не удаётся запустить поток приёма соединений
link-no-port-named = { $url } не называет последовательный порт
link-hint-port-example = например { $example } (`plcsh ports` перечисляет последовательные порты этого компьютера)
link-unknown-carrier = `+{ $carrier }` в { $url } — не способ связи с последовательной линией
link-hint-carriers = используйте +tcp://HOST:PORT (raw TCP-порт сервера устройств) или +rfc2217://HOST:PORT
link-cannot-list-ports = не удаётся получить список последовательных портов
link-hint-list-ports-dev = ls /dev/ttyUSB* /dev/ttyACM* /dev/serial/by-id показывает порты, которые видит ядро
link-hint-list-ports-device-manager = Диспетчер устройств → Порты (COM и LPT) показывает порты, которые видит Windows
k2-no-option = у устройств K2 по линии связи нет параметра `{ $key }`
k2-hint-options = параметры: word_order (high-first, low-first), timeout, retries, agent
k2-retries-not-number = `retries={ $value }` не число
k2-not-scheme = `{ $scheme }:` не схема связи с K2
k2-cannot-start-runtime = не удаётся запустить среду выполнения для присоединённого потока
k2-attached-failed = присоединённый поток дал сбой, и plcsh не может открыть его заново
k2-hint-reopen = { $hint }; следующая команда откроет его снова, когда он вернётся
k2-reply-too-short = ответ на чтение { $span } слишком короткий
k2-request = { $doing ->
        [reading] чтение
       *[writing] запись
    } { $operand }{ $more ->
        [0] {""}
       *[other] {" "}и ещё { $more }
    } ({ $span }, FC { $fc })
k2-while = { $what }: { $message }
k2-refused = ПЛК отказал ({ $what }): { $exception } (исключение Modbus { $code })
k2-hint-exception-1 = этот ПЛК не поддерживает этот код функции на этом порту
k2-hint-exception-2 = адрес вне карты Modbus ПЛК; проверьте, что model={ $model } соответствует ПЛК
k2-hint-exception-3 = ПЛК отказал из-за размера или значения запроса (пределы: чтение 1600 бит или 100 регистров, запись 800 бит или 100 регистров)
k2-hint-exception = смотрите диагностику ПЛК
k2-hint-connect = проверьте, что HOST:PORT — это ПЛК или шлюз (K204ET отвечает по Modbus TCP на порту 502), что он включён и доступен (ping) и что порт не закрыт межсетевым экраном
k2-writes-before = { $message }; { $sent ->
        [one] { $sent } запрос записи перед ним был отправлен
        [few] { $sent } запроса записи перед ним были отправлены
       *[many] { $sent } запросов записи перед ним были отправлены
    }
link-not-parity = `parity={ $parity }` в { $url } не четность
link-hint-parity = используйте parity=none, parity=even или parity=odd
link-not-stop-bits = `stop={ $stop }` в { $url } не 1 и не 2
link-baud-zero = `baud=0` в { $url } не скорость передачи данных
link-not-unit-id = `unit={ $unit }` в { $url } не адрес ведомого устройства Modbus
link-hint-unit-id = адреса ведомых устройств — 1…247 (0 — широковещательный, на него нет ответа)
link-cannot-use-connection = не удаётся использовать соединение с { $addr }

## Командная строка (cli)

cli-about = Оболочка для пусконаладки и отладки ПЛК Kinco K2 и сервоприводов
cli-opt-command = Выполнить эти команды (через `;`) и выйти
cli-opt-json = Выводить по одному объекту JSON на результат каждой команды
cli-opt-verbose = Показывать больше: каждый отправленный и принятый кадр в hex с временем, число запросов, частоту выборок
cli-opt-model = Модель ПЛК, симулируемого по умолчанию
cli-opt-device = Добавить устройство: NAME=URL, NAME=PROFILE, просто PROFILE (открывается под своим именем и становится текущим) или просто URL (заменяет `plc`). Можно повторять
cli-opt-time = Время симулятора: идёт по реальным часам или движется только шагами
cli-opt-config = Файл профилей устройств (по умолчанию PLCSH_CONFIG, иначе { $file }).
cli-opt-state = Файл состояния симулятора (область резервного копирования данных, сохраняющиеся диапазоны, часы); по умолчанию PLCSH_STATE, иначе в каталоге данных пользователя; `none` ничего не читает и не пишет (лабораторные работы, тесты). `sim serve` хранит состояние только с --state FILE
cli-opt-record = Записывать каждый кадр на каждой линии связи с устройствами в FILE (pcapng; `plcsh record show FILE`)
cli-opt-bench = Открыть симулируемую установку, описанную файлом стенда (устройства, связи, начальные значения)
cli-opt-read-only = Отказывать в любом изменении любого устройства (запись, инструкции, команды сервопривода): осмотр работающей установки
cli-opt-fleet = Выполнить команды -c (или скрипт `run`) на всех устройствах этой группы из файла профилей одновременно (docs/fleets.md)
cli-opt-jobs = С --fleet: со сколькими устройствами работать одновременно
cli-opt-lang = Язык сообщений: en, ru, zh-CN (по умолчанию PLCSH_LANG, иначе язык системы; английский, если ни то ни другое не называет один из них)
cli-opt-device-timeout = С --fleet: устройство, занятое дольше этого, считается тайм-аутом (`30s`, `2m`; 0 — без ограничения)
cli-opt-tags = Файл тегов (CSV, TOML или IEC VAR_GLOBAL), имена из которого работают везде, где операнд: FILE — для текущего устройства, DEVICE=FILE — для другого (docs/tags.md). Можно повторять
cli-sub-models = Каталог моделей K2; `models MODEL` показывает одну модель полностью (области, счетчики, примечания руководства)
cli-sub-devices = Открытые устройства и профили устройств (devices.toml) с ошибками в этом файле
cli-sub-ports = Имеющиеся последовательные порты с USB-адаптером (VID:PID, изделие, серийный номер)
cli-sub-paths = Где лежит каждый файл: профили, модули Lua, состояние, история, снимки, флеш-память УМПК, записи
cli-sub-man = Вывести страницу руководства (roff), составленную из этих параметров и команд оболочки: plcsh man > plcsh.1
cli-sub-completions = Вывести скрипт дополнения для оболочки (bash, zsh, fish, powershell) или записать их все
cli-sub-sim = Предоставить симуляторы другим программам: `sim serve` выставляет симулируемый K2 по Modbus TCP / RTU, а сервоприводы — { $served ->
        [tcp] на TCP-порт (как есть или RFC 2217, до которого дотягивается пара COM-портов, например com0com)
       *[pty] на pty или TCP-порт (как есть или RFC 2217)
    }.
cli-sub-agent = Вспомогательная программа в ПЛК, дающая plcsh регистры SM и инструкции на настоящем K2
cli-sub-probe = Что K2 отвечает по Modbus до установки вспомогательной программы: области и их последние адреса, подходящие модели, время ответа; только чтение (docs/reference/first-connection.md)
cli-sub-run = Выполнить скрипт Lua: plcsh [--time stepped] [--device NAME=URL] run SCRIPT.lua [ARGS…]
cli-sub-record = Записи, сделанные с --record: `record show FILE` выводит расшифрованную временную шкалу
cli-sub-replay = Повторить запросы записи на симуляторе и сообщить о каждом ответе, который отличается
cli-sub-lab = Лабораторные работы: `lab new NAME`, `lab check LAB`, `lab grade LAB SUBMISSIONS…` (в песочнице, параллельно)
cli-sub-publish = Опрашивать операнды устройства или группы и публиковать их на брокер MQTT (docs/fleets.md)
cli-sub-tags = Таблицы тегов (docs/tags.md): `tags FILE` показывает имена, `tags check FILE` проверяет их, `tags export FILE --to csv|iec` записывает их в другой форме
cli-lab-new = Записать в NAME рабочий пример лабораторной работы (K2 и сервопривод со связями, заготовка IL, программа оценки на Lua)
cli-lab-new-name = Каталог новой работы
cli-lab-check = Проверить работу: её lab.toml, файлы и начальное состояние, и программу оценки на эталонном решении
cli-lab-arg-lab = Каталог работы (или её lab.toml)
cli-lab-grade = Оценить сданные работы (файлы или каталоги с файлами .lua / .il), каждую в новом рабочем процессе в песочнице
cli-lab-grade-submissions = Файлы или каталоги сданных работ
cli-lab-grade-jobs = Сколько рабочих процессов одновременно (по умолчанию по одному на ядро)
cli-lab-grade-junit = Записать результаты ещё и в FILE в формате JUnit XML
cli-lab-grade-show-output = Показать, что вывела каждая работа (stdout и stderr, первые 64 КиБ каждого); `--json` всегда передаёт их как `stdout` и `stderr`
cli-heading-usage = Использование:
cli-heading-commands = Команды
cli-heading-arguments = Аргументы
cli-heading-options = Параметры
cli-heading-global = Общие параметры
cli-help-flag = Показать справку
cli-version-flag = Показать версию
cli-hint-shell-command = `{ $line }` — команда оболочки: plcsh -c '{ $line }'

## Справка и карточка команд (shell::commands::help): что делает каждая команда, экраны справки

summary-get = прочитать операнды (можно диапазоны и префикс устройства device:)
summary-set = записать операнды по порядку; вся строка проверяется до того, как что-либо будет записано
summary-read = прочитать диапазон в виде таблицы: значение, hex и двоичный вид
summary-use = сделать DEVICE устройством, к которому относятся операнды без префикса
summary-devices = список открытых устройств и профилей устройств
summary-connect = открыть устройство под именем или профиль устройства из devices.toml
summary-close = закрыть устройство
summary-sim = часы симулятора (показать, сделать шаг и остаться в пошаговом режиме, следовать реальному времени), входные сигналы счетчиков, сохраняющиеся диапазоны, CPU, выполняющий программу IL, связи между симулируемыми устройствами, снимки состояния симулятора, внесённые неисправности
summary-watch = живая таблица операндов, обновляется на месте до Ctrl-C или count=N; изменения выделены
summary-trace = записывать значения операндов во времени (для `plot`), по желанию в файл CSV
summary-plot = нарисовать последнюю запись trace в терминале, а с to= ещё и картинкой PNG или SVG (импульсный выход — его частотой)
summary-servo = работа с сервоприводом Kinco: автомат состояний DS402, перемещения, JOG (Бег), возврат в исходное положение, ожидания, единицы, кадры как есть
summary-umpk = учебные ПЛК УМПК8/УМПК16: сведения о контроллере и программе, история ошибок, время цикла, сброс, эхо, монитор реального времени, запись программы Intel HEX
summary-pls = выполнить инструкцию PLS на импульсном канале N (0 = Q0.0, 1 = Q0.1, 2 = Q0.4, 3 = Q0.5 на K209M)
summary-pstop = аварийный останов импульсного канала N (фиксирует SM201.7 …; сброс: set SM201.7=0)
summary-pto = запустить односегментную последовательность импульсов (пишет SMB67, SMW68, SMD72, затем PLS) или расшифровать её состояние
summary-pwm = запустить широтно-импульсную модуляцию PWM на канале N (пишет SMB67=16#D3, SMW68, SMW70, затем PLS)
summary-profile = многосегментный PTO по таблице профиля (пишет таблицу, SMW168, SMB67=16#A0, затем PLS); `plan` только рисует частоту во времени
summary-hdef = выполнить инструкцию HDEF: задать режим высокоскоростного счетчика HSC N (§3.3.1)
summary-hsc = выполнить инструкцию HSC; с параметрами — сначала записать регистры счетчика (затем HDEF, HSC); или расшифровать его состояние
summary-events = показать события прерываний, произошедшие до сих пор, с их виртуальным временем и очистить журнал (`keep` оставляет его)
summary-wait = ждать, пока устройство не выдаст событие прерывания (берётся из журнала); пошаговое время перескакивает вперёд
summary-rtc = прочитать часы реального времени ПЛК, установить их или установить по местному времени компьютера
summary-eeprom = сохранить или загрузить область резервного копирования данных E2PROM (VB3648…) двоичным файлом; показать счетчики записей; задать конец области
summary-data = наборы данных: сохранить типизированные значения операндов в файл, сравнить файл с устройством или другим файлом, загрузить только различия
summary-lua = выполнить Lua в состоянии Lua сеанса (устройства — глобальные переменные: plc.VW100 = 5)
summary-agent = проверить вспомогательную программу в ПЛК, которая даёт доступ к регистрам SM и инструкциям по Modbus (docs/agent.md)
summary-lab = лабораторные работы: создать пример работы, проверить работу по эталонному решению, оценить сданные работы (в песочнице, параллельно)
summary-models = каталог моделей K2; одна модель полностью (области, счетчики, импульсные выходы, примечания руководства)
summary-ports = имеющиеся последовательные порты с USB-адаптером (VID:PID, изделие, серийный номер)
summary-paths = где лежит каждый файл: профили, модули Lua, состояние, история, снимки
summary-help = список команд или описание одной команды (все её формы) или операнда
summary-quit = выйти из оболочки

help-groups-heading = команды по группам (`help all` показывает каждую с описанием):
help-group = { $group ->
    [io] чтение и запись
    [devices] устройства
    [simulator] симулятор
    [pulse] импульсные выходы
    [counters] счетчики
    [interrupts] прерывания
    [plc] ПЛК
    [servo] сервопривод, УМПК
    [scripts] скрипты, лабораторные
   *[shell] эта оболочка
}
help-footer = `help COMMAND`: формы команды (`help pto`); `help sim step`: формы подкоманды. `help VW100`, `help SMB67`: что такое операнд. Tab дополняет команды, операнды и параметры (`pto 0 fr` ⇥ `freq=`).
help-all-heading = команды (`help COMMAND` показывает формы команды и её подкоманды):
help-all-footer = операнды: `help VW100`, `help SMB67` объясняют операнд; Tab дополняет их
help-sub-commands = подкоманды: { $list }
help-no-topic = нет команды или операнда `{ $topic }`
help-extra-word = help принимает команду и одну подкоманду (после них стоит `{ $word }`)
help-no-sub-command = у `{ $command }` нет подкоманды `{ $sub }`
shell-takes-nothing = после { $command } ничего не пишется (стоит `{ $word }`)
man-shell-commands = КОМАНДЫ ОБОЛОЧКИ
man-shell-commands-intro = Вводятся в приглашении plcsh>, передаются в -c (несколько через ;) или выполняются из Lua через plcsh.exec. help перечисляет их по группам, help COMMAND показывает формы команды.

## Лабораторные работы (lab): строки, таблицы и итоги оценки и проверки на языке `language` работы

lab-new-wrote = записана работа { $dir } ({ $files }); проверьте её: plcsh lab check { $dir }
lab-grade-head = { $lab }: { $count ->
        [one] { $count } сданная работа
        [few] { $count } сданные работы
       *[many] { $count } сданных работ
    }, все критерии выполнены в { $passed }
lab-duplicate-student = Внимание: у { $count ->
        [one] { $count } сданной работы
       *[other] { $count } сданных работ
    } одно имя студента { $student }: { $files }
lab-grade-columns = студент | баллы | выполнено | не выполнено | итог | время симуляции
lab-check-columns = критерий | баллы | результат
lab-verdict = { $verdict ->
        [passed] зачтено
       *[failed] не зачтено
    }
lab-criterion-ok = выполнен
lab-not-reached = не достигнут
lab-expected = ожидалось { $expected }, получено { $got }
lab-expected-at = ожидалось { $expected }, получено { $got } в момент { $at } с
lab-expected-what = { $what }: ожидалось { $expected }, получено { $got }
lab-expected-what-at = { $what }: ожидалось { $expected }, получено { $got } в момент { $at } с
lab-error-at = { $error } в момент { $at } с
lab-free-points-starter = заготовка { $file } набирает { $points } из { $max ->
        [one] { $max } балла
       *[other] { $max } баллов
    } ({ $criteria }): критерий, который программа проходит, не выполняя задания, ничего из задания не проверяет
lab-free-points-empty = пустая программа набирает { $points } из { $max ->
        [one] { $max } балла
       *[other] { $max } баллов
    } ({ $criteria }): критерий, который программа проходит, не выполняя задания, ничего из задания не проверяет
lab-points-no-criterion = { $file }: [points] "{ $key }" не называет ни одного критерия, определённого программой оценки (на эталонном решении)
lab-hint-did-you-mean-criterion = может быть, "{ $near }"? программа оценки определяет: { $criteria }
lab-hint-no-criteria = программа оценки не определяет ни одного критерия (lab.criterion(name, points, fn))
lab-hint-criteria = программа оценки определяет: { $criteria }
lab-check-passed = { $lab }: эталонное решение набирает { $points } из { $max ->
        [one] { $max } балла
       *[other] { $max } баллов
    } за { $time } с симуляции
lab-check-failed = { $lab }: эталонное решение набирает { $points } из { $max ->
        [one] { $max } балла
       *[other] { $max } баллов
    } ({ $verdict }): исправьте программу оценки или эталонное решение

## Опрос (k2::probe, cli::probe): что K2 отвечает до установки вспомогательной программы

probe-head = опрос { $url }: { $requests ->
        [one] { $requests } запрос
        [few] { $requests } запроса
       *[many] { $requests } запросов
    } на чтение, без записи
probe-serial-answered = параметры связи, на которые пришёл ответ: { $settings }
probe-serial-tried = опробованные параметры связи без ответа: { $settings }
probe-columns = таблица | FC | область | первый | последний | единиц | чтений | результат
probe-models = подходящие модели: { $models }
probe-models-none = подходящие модели: нет
probe-verdict = { $ok ->
        [ok] в порядке
       *[failed] ОШИБКА
    }: { $what }
probe-what-to-do = что делать: { $todo }
probe-result-answers = отвечает
probe-result-no-end = отвечает до следующей области: конец не найден
probe-result-absent = отсутствует (исключение 02 на первом адресе)
probe-result-refused = исключение { $code } ({ $name }) на адресе { $address }
probe-result-no-reply = нет ответа на адресе { $address }
probe-no-answer = ПЛК не ответил на чтение { $table } { $address }: { $message }
probe-refused = { $table } { $address } ({ $area }, FC { $fc }): отказ с исключением { $code } ({ $name })
probe-no-reply = { $table } { $address } ({ $area }, FC { $fc }): нет ответа: { $message }
probe-todo-link-again = { $hint }; затем опросите снова
probe-no-model = ни у одной модели каталога нет таких размеров областей ({ $sizes })
probe-todo-no-model = подключайтесь с ближайшей model= (их перечисляет plcsh models) и приложите этот отчёт (--report FILE) к вопросу: в каталоге plcsh может не быть этого ПЛК
probe-models-fit = размеры областей подходят { $count ->
        [one] модели
       *[other] моделям
    } { $models }
probe-todo-same-areas = у этих моделей одинаковые области Modbus: укажите в model= ту, что на этикетке ПЛК
probe-no-mailbox = V как регистры хранения не отвечает до регистра { $register } (VB{ $first } … VB{ $last }, почтовый ящик вспомогательной программы по умолчанию)
probe-todo-mailbox = регистрам SM и инструкциям нужен почтовый ящик вспомогательной программы в V: выберите базовый адрес, на который ПЛК отвечает (plcsh agent il --base VB…)
probe-timed-failed = { $failed } из { $reads } замеренных чтений { $what } остались без ответа или получили исключение
probe-todo-link-slow = { $hint }; линия, теряющая ответы, замедляет каждую команду (plcsh повторяет запросы)
probe-timed = { $reads ->
        [one] { $reads } чтение
        [few] { $reads } чтения
       *[many] { $reads } чтений
    } { $what }: p50 { $p50 } мс, p99 { $p99 } мс
probe-todo-exception-01 = порт не принимает этот код функции чтения: проверьте, что это порт Modbus ПЛК (PORT1/PORT2 настроен в KincoBuilder как ведомый Modbus RTU, или Modbus TCP на K204ET), а не порт программирования или свободного протокола
probe-todo-exception-04 = ПЛК сообщает об отказе устройства: проверьте светодиод ошибки и диагностику в KincoBuilder, затем опросите снова
probe-todo-exception-06 = ПЛК занят: опросите снова; если он остаётся занятым, его занимает что-то другое (другой ведущий, загрузка программы)
probe-todo-gateway = за ПЛК ответил шлюз: проверьте маршрут шлюза к ПЛК (адрес ведомого устройства, параметры связи, проводку)
probe-todo-attach = приложите этот отчёт к вопросу: plcsh probe … --report FILE

## REPL (shell::repl): первые строки
repl-banner = plcsh { $version } — `help` перечисляет команды, `quit` — выход.
repl-devices = Устройства: { $devices }
repl-device-simulated = { $name } ({ $model }, симулятор)
repl-no-line-editor = не удаётся запустить редактор строки: { $error }
repl-input-error = ошибка ввода: { $error }

## Снимки состояния симулятора (shell::commands::snapshot)
snapshot-list-sandboxed = `sim snapshots` показывает каталог данных пользователя: не в запуске в песочнице
snapshot-hint-sandboxed = запуск в песочнице хранит снимки файлами в своём каталоге для записи
snapshot-none = сохранённых снимков нет (sim snapshot save NAME)
snapshot-columns = снимок | файл
snapshot-one-name = `sim snapshot { $verb }` принимает одно имя или файл, а не { $count ->
        [one] { $count } слово
        [few] { $count } слова
       *[many] { $count } слов
    }
snapshot-hint-quotes = путь с пробелами пишется в кавычках: sim snapshot { $verb } { $path }
snapshot-needs-verb = `sim snapshot` нужны save или restore и имя: { $usage }
snapshot-saved = { $devices } в момент { $time } сохранены в { $file }
snapshot-restored = { $devices } восстановлены на момент { $time }
snapshot-unknown = неизвестная команда `sim snapshot { $verb }`

## Оболочка (shell)

shell-unknown-command = неизвестная команда `{ $name }`
shell-hint-did-you-mean = может быть, `{ $name }`? `help` перечисляет команды
shell-hint-help = `help` перечисляет команды
shell-hint-subcommand = может быть, `{ $command } { $near }`? `help { $command }` показывает, как её вызывать

## Servo parameter sets (servo::params, servo params)

servo-params-cannot-read = не удаётся прочитать { $file }
servo-params-bad-file = { $file } — не файл набора параметров: { $reason }
servo-params-other-drive = { $file } содержит параметры привода { $kind }, а этот привод — { $expected }: набор загружается только в привод того типа, с которого он прочитан
servo-params-unknown-object = { $file } называет параметр { $name } объектом { $object }/{ $dtype }, а в словаре объектов этого привода такого параметра нет: файл от привода другого типа или изменён вручную
servo-params-duplicate = { $file } перечисляет параметр { $name } дважды
servo-params-out-of-range = { $file }: { $value } вне диапазона параметра { $name }
servo-params-unknown-group = неизвестная группа параметров `{ $group }`; группы: { $groups }
servo-params-read-back = { $name } ({ $object }) после записи { $value } читается как { $back }; загрузка остановлена
servo-params-stopped = загрузка остановлена на { $name } ({ $object }) после { $written ->
        [one] { $written } записи
       *[other] { $written } записей
    }: { $reason }
servo-params-usage = как вызывать: servo params save FILE [group…] | servo params diff FILE [FILE2] | servo params diff --with DRIVE | servo params load FILE [--store]
servo-params-saved = { $count ->
        [one] сохранён { $count } параметр
        [few] сохранено { $count } параметра
       *[many] сохранено { $count } параметров
    } в { $file }; отказано или нет: { $refused }
servo-params-same = различий нет
servo-params-loaded = { $written ->
        [one] записан { $written } параметр
        [few] записано { $written } параметра
       *[many] записано { $written } параметров
    }, каждый прочитан обратно; без изменений: { $unchanged }
servo-params-loaded-stored = { $written ->
        [one] записан { $written } параметр
        [few] записано { $written } параметра
       *[many] записано { $written } параметров
    }, каждый прочитан обратно; без изменений: { $unchanged }; параметры сохранены в памяти привода (2FF0.01 = 1)

## Внесённые неисправности симуляторов, общие для симуляторов K2, УМПК и FX (core::sim_faults, k2::sim::control)

sim-fault-describe = неисправность { $id }: { $what } с { $from } с до сброса
sim-fault-describe-until = неисправность { $id }: { $what } с { $from } с до { $until } с
sim-control-words-hint = управляющие слова: { $words }
sim-not-level = `{ $value }` — не уровень (1, 0, on, off)
sim-not-option-here = `{ $word }` здесь не параметр (for=DURATION)
sim-word-takes-nothing = после `{ $word }` ничего не пишется (получено `{ $rest }`)
sim-no-faults = внесённых неисправностей нет
sim-no-fault-acted = ни одна внесённая неисправность не сработала
sim-fault-acted = { $seconds } с: сработала неисправность { $id } ({ $name })
sim-not-fault-id = `{ $text }` — не номер неисправности
sim-no-such-fault = неисправности { $id } нет
sim-no-such-fault-hint = `faults` перечисляет их
sim-faults-cleared = { $n ->
    [one] сброшена { $n } неисправность
    [few] сброшено { $n } неисправности
   *[many] сброшено { $n } неисправностей
}
sim-stuck-needs-input = fault stuck нужны вход и уровень: stuck IN=1
sim-stuck-shape = `{ $spec }`: пишите stuck { $spec }=1 или stuck { $spec }=0
sim-not-fault-here = `{ $kind }` здесь не неисправность (no-reply, stuck)
sim-which-fault = какая неисправность? fault no-reply | fault stuck IN=1

## Файлы (core::durable)

file-cannot-create = не удаётся создать { $path }
file-cannot-open = не удаётся открыть { $path }
file-cannot-write = не удаётся записать { $path }

## Профили устройств и группы (profile, profile::fleet)

profile-cannot-read = не удаётся прочитать: { $error }
profile-file-not-loaded = { $error } (ни один профиль из этого файла не загружен)
profile-skipped = профиль `{ $name }` пропущен: { $reason }
profile-unknown = `{ $name }` — не URL устройства и не профиль
profile-unknown-define-hint = укажите URL (sim:MODEL, tcp://HOST:PORT …) или опишите { $section } в { $file }
profile-unknown-list-hint = профили в { $file }: { $list }
profile-name-letters = имя профиля — только латинские буквы A-Z a-z, цифры, _ и - (оно становится именем устройства и пишется перед операндами: press1:VW0)
profile-url-not-string = `url` должен быть строкой
profile-url-missing = нет `url` (например, { $example })
profile-read-only-bool = `read_only` должен быть true или false
profile-allow-list = `allow` должен быть списком операндов, например { $example }
profile-option-scalar = параметр `{ $key }` должен быть строкой, числом или логическим значением
profile-options-table = `options` должен быть таблицей
profile-key-scalar = `{ $key }` должен быть строкой, числом или логическим значением
profile-unknown-scheme = неизвестная схема устройства `{ $scheme }:` в { $url }
profile-known-schemes-hint = известные схемы: { $list }
profile-allow-item = профиль `{ $name }` ({ $origin }): элемент allow `{ $item }`: { $reason }
profile-allow-item-hint = элементы allow — операнды или диапазоны этого устройства, например "VW100..VW120"
profile-read-only-refused = { $what ->
    [none] запись отклонена: профиль `{ $profile }` — read_only ({ $origin })
   *[other] { $what } отклонено (меняет { $name }): профиль `{ $profile }` — read_only ({ $origin })
}
profile-read-only-refused-hint = чтение работает; чтобы записывать, уберите `read_only = true` из профиля
profile-allow-refused = { $what ->
    [none] запись отклонена: { $name } нет в списке allow профиля `{ $profile }` [{ $list }] ({ $origin })
   *[other] { $what } отклонено (меняет { $name }): { $name } нет в списке allow профиля `{ $profile }` [{ $list }] ({ $origin })
}
profile-allow-refused-hint = запись разрешена только в перечисленные операнды, того же размера
profile-summary-read-only = только для чтения
profile-summary-allow = allow { $list }
fleet-needs-range = группе по URL нужен один диапазон вида { $example } в url
fleet-unclosed-brace = `{"{"}` без `{"}"}` в url
fleet-one-range = в url группы допустим только один диапазон { $form }
fleet-not-range = `{ $range }` — не диапазон (пишите { $form })
fleet-not-number = `{ $text }` в `{ $range }` — не число
fleet-backwards = диапазон { $range } идёт в обратную сторону
fleet-too-many = диапазон { $range } называет устройств: { $n }; в группе не больше { $max }
fleet-devices-or-url = укажите `devices` или `url`, но не оба
fleet-needs-devices = группе нужен `{ $devices }` или `{ $url }`
fleet-devices-list = `devices` должен быть списком имён профилей или URL
fleet-devices-empty = `devices` пуст
fleet-devices-rules = `{ $key }`: группа `devices` берёт правила из каждого профиля
fleet-listed-twice = `{ $name }` указан дважды
fleet-lists-unknown = группа `{ $name }` ({ $origin }) называет `{ $profile }`, но такой профиль не загружен
fleet-unknown = группы `{ $name }` нет
fleet-unknown-define-hint = опишите { $section } с { $devices } или { $url } в { $file }
fleet-unknown-list-hint = группы в { $file }: { $list }
fleet-name-letters = имя группы — только латинские буквы A-Z a-z, цифры, _ и -
fleet-skipped = группа `{ $name }` пропущена: { $reason }

## URL устройств и файлы (schemes, paths, pending)

schemes-known-hint = известные схемы: sim:MODEL, tcp://HOST:PORT, rtu:PORT, kinco:PORT?id=1, sim-servo:?id=1, fx:PORT, fxlink:PORT, sim-fx:FX2N, umpk:PORT, sim-umpk:UMPK16 (PORT: COM3, /dev/ttyUSB0; сервер последовательных устройств: rtu+tcp://HOST:PORT, kinco+rfc2217://HOST:PORT, …)
pending-not-connected = `{ $operand }` пока не прочитать: устройство не подключено
pending-not-connected-hint = проверьте связь (`plcsh ports`, кабель, питание); следующая команда снова попробует подключиться

## URL устройств, текстовые файлы, параметры (core::url, core::encoding, core::device, core::signal)

url-not-url = `{ $text }` — не URL устройства
url-not-url-hint = используйте sim:MODEL, tcp://HOST:PORT?unit=1, { $rtu }, rtu+tcp://HOST:PORT, { $kinco } или sim-servo:?id=1
url-param-too-large = `{ $param }` в { $url } слишком велик: не больше { $max }
url-param-not-number = `{ $param }` в { $url } — не целое число
url-unknown-param = неизвестный параметр `{ $key }` в { $url }
url-known-params-hint = известные: { $list }
encoding-utf16-kind = { $kind ->
    [bom-le] текст UTF-16 (метка порядка байт FF FE)
    [bom-be] текст UTF-16 (метка порядка байт FE FF)
    [le] текст UTF-16 little-endian без метки порядка байт (NUL после каждого символа ASCII)
   *[be] текст UTF-16 big-endian без метки порядка байт (NUL перед каждым символом ASCII)
}
encoding-utf16-odd = { $what } обрывается посреди символа на байте { $byte } (сохраните файл в UTF-8)
encoding-utf16-surrogate = { $what }: неверный UTF-16 на байте { $byte }: одиночный суррогат { $surrogate } (сохраните файл в UTF-8)
device-no-option = у устройств { $family } нет параметра `{ $key }`
signal-freq-positive = частота импульсов { $freq } Гц должна быть положительной
