# plcsh messages (ru): k2 — драйвер, симулятор и помощники K2, схемы соединений и снимки. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## Импульсные выходы: pto, pwm, profile (k2::helpers::pto; руководство §3.4)

k2-pto-rounded = { $hz } Гц не даёт целого числа мкс: время цикла { $us } мкс = { $actual } Гц
k2-pto-relay-model = у { $model } релейные выходы: PTO/PWM нет (руководство §2.2.6)
k2-pto-relay-model-hint = для высокоскоростного импульсного выхода нужна модель с транзисторными выходами, например K205-16DT
k2-pto-no-channel = у { $model } нет импульсного канала { $channel }
k2-pto-no-channel-hint = импульсные каналы: { $list }
k2-pto-cycle-register = { $us } мкс не помещается в регистр времени цикла: до 65 535 мкс или целое число миллисекунд до 65 535 мс
k2-pto-cycle-below-minimum = время цикла { $us } мкс меньше минимума 2 (§3.4.2.2)
k2-pto-cycle-too-short = время цикла { $us } мкс слишком мало для { $output }: наименьшее время цикла { $shortest } мкс ({ $max } Гц, руководство §3.4)
k2-pto-cycle-too-short-hint = cycle={ $shortest }us или больше; cycle= задаётся в мкс, если единица не указана (cycle=1ms)
k2-pto-freq-too-high = { $hz } Гц выше предела { $output }, { $max } Гц (руководство §3.4)
k2-pto-freq-too-high-hint = наименьшее время цикла на { $output } — { $shortest } мкс
k2-pto-count-range = count={ $count }: PTO нужно от 2 до 4 294 967 295 импульсов (§3.4.2.1)
k2-pto-ms-base = время цикла { $us } мкс использует временную базу 1 мс (SM{ $control }.3 = 1)
k2-pwm-width-whole-ms = width={ $width } мкс: при времени цикла { $cycle } мкс временная база 1 мс, поэтому длительность импульса должна быть целым числом мс
k2-pwm-always-on = длительность импульса ≥ времени цикла: рабочий цикл 100 %, выход остаётся включённым (§3.4.2.1)
k2-pwm-always-off = длительность импульса 0: рабочий цикл 0 %, выход остаётся выключенным (§3.4.2.1)
k2-table-odd-hint = например, at VB{ $at }
k2-profile-even = VB{ $at } — чётный адрес: таблица профиля должна начинаться с нечётного адреса V (§3.4.2.1)
k2-profile-segments = { $n ->
    [one] { $n } сегмент
    [few] { $n } сегмента
   *[many] { $n } сегментов
}: в профиле от 1 до { $max } сегментов
k2-profile-past-v = таблица VB{ $at }…VB{ $last } выходит за конец области V { $model } (VB{ $top })
k2-profile-backup = таблица VB{ $at }…VB{ $last } перекрывает область резервного копирования данных E2PROM VB{ $first }…VB{ $end } (§2.2.8): каждая запись изнашивает её
k2-table-backup-hint = перенесите таблицу ниже VB3648 или добавьте `force`
k2-profile-segment = сегмент { $n }
k2-profile-segment-count = сегмент { $n }: count={ $count } (от 1 до 4 294 967 295)
k2-profile-segment-error = сегмент { $n }: { $message }
k2-profile-ms-base = профиль использует временную базу 1 мс (SM{ $control }.3 = 1)
k2-profile-mixed-base = все сегменты используют одну временную базу (§3.4.2.1): части значений цикла нужны единицы 1 мс (> 65 535 мкс), а другие не кратны целой мс
k2-pto-control-bit = { $bit ->
    [enabled] включён
    [disabled] отключён
    [sync] синхронное обновление
    [async] асинхронное обновление
    [multi] многосегментный
    [single] односегментный
    [base-ms] временная база 1 мс
    [base-us] временная база 1 мкс
    [cycle] обновлять время цикла
    [width] обновлять длительность импульса
   *[count] обновлять количество импульсов
}
k2-pto-status-bit = { $bit ->
    [pto-idle] PTO в режиме ожидания
    [pto-busy] PTO занят
    [pwm-idle] PWM в режиме ожидания
    [pwm-running] PWM работает
    [invalid] время цикла или число импульсов неверное
   *[aborted] прекращён командой пользователя
}
k2-pto-status-control = байт управления: { $words }
k2-pto-status-position = позиция { $pulses ->
    [one] { $pulses } импульс
    [few] { $pulses } импульса
   *[many] { $pulses } импульсов
}
k2-pto-status-estop = аварийный останов зафиксирован (SM{ $byte }.7)
k2-pto-status-dir-off = выход направления отключён (SM{ $byte }.3)
k2-pto-busy = PTO{ $channel } ещё выдаёт последовательность импульсов (SM{ $byte }.7 PTO в режиме ожидания = 0)
k2-pwm-busy = PWM{ $channel } работает (SM{ $byte }.3 PWM в режиме ожидания = 0)

## Высокоскоростные счетчики: hsc (k2::helpers::hsc; руководство §3.3)

k2-hsc-no-counter = у { $model } нет высокоскоростного счетчика HSC{ $n }
k2-hsc-no-counter-hint = счетчики { $model }: { $list }
k2-hsc-no-mode = у HSC{ $n } нет режима { $mode } (руководство §3.3.1)
k2-hsc-no-mode-hint = режимы HSC{ $n }: { $list }
k2-hsc-rate-4x = rate=4x относится к режимам с фазой AB (9, 10), а не к режиму { $mode }
k2-hsc-dir = режим { $mode } берёт направление счета со своих входов; dir= относится к режимам 0–2 (§3.3.2)
k2-hsc-no-reset = у режима { $mode } нет входа сброса
k2-hsc-no-start = у режима { $mode } нет входа старта
k2-hsc-cyclic-relative = циклическим прерываниям CV = PV нужны относительные PV (§3.3.2: SM141.2 действует только вместе с SM141.1)
k2-hsc-table-needs-at = таблице PV (несколько PV, относительные или циклические) нужен адрес V: добавьте `at VB3009`
k2-hsc-at-needs-pv = для `at` нужны PV: pv=[100,200,300]
k2-hsc-even = VB{ $at } — чётный адрес: таблица PV начинается с нечётного адреса V (§3.3.2)
k2-hsc-too-many-pvs = { $n } PV: у счетчика не больше { $max } (§3.3.3)
k2-hsc-past-v = таблица PV VB{ $at }…VB{ $last } выходит за конец области V { $model } (VB{ $top })
k2-hsc-backup = таблица PV VB{ $at }…VB{ $last } перекрывает область резервного копирования данных E2PROM VB{ $first }…VB{ $end } (§2.2.8)
k2-hsc-pv-ends-table = PV{ $index } = { $pv } завершит таблицу на этом месте (§3.3.3: относительное |PV| > 1, соседние абсолютные различаются больше чем на 1)
k2-hsc-events = события CV = PV { $first }…{ $last } (§3.3.4)
k2-hsc-status-bit = { $bit ->
    [up] счёт вверх
    [down] счёт вниз
    [equal] CV = PV
    [greater] CV > PV
    [fault] неисправность в табличных значениях PV
    [enabled] включён
   *[disabled] отключён
}
k2-hsc-status-cv = CV { $cv }
k2-hsc-status-written-cv = SMD{ $smd } содержит записанное { $value }: новое текущее значение, загрузится следующей HSC { $n } при установленном SM{ $control }.6 (§3.3.2)
k2-hsc-status-multi-pv = { $kind ->
    [relative] несколько PV, относительные, сегмент { $segment }
    [relative-cyclic] несколько PV, относительные, циклические, сегмент { $segment }
    [absolute-cyclic] несколько PV, абсолютные, циклические, сегмент { $segment }
   *[absolute] несколько PV, абсолютные, сегмент { $segment }
}
k2-hsc-status-single-pv = одно PV { $pv }

## Выполнение плана помощника (k2::helpers)

k2-not-a-k2 = это устройство — не ПЛК K2
k2-duration-not-positive = `{ $text }` — не положительная длительность

## Операнды: что это за операнд, `help ОПЕРАНД`, дополнение (k2::space)

k2-describe-overlaps = перекрывает { $names }
k2-describe-pulse-output = дискретный выход; высокоскоростной импульсный выход PTO{ $channel }/PWM{ $channel } (до { $khz } кГц)
k2-describe-direction-output = дискретный выход; выход направления канала позиционирования { $channel }
k2-describe-v-backup = область V, в области резервного копирования данных E2PROM (VB3648–VB4095, §2.2.8)
k2-help-type = тип { $dtype } ({ $bits ->
    [one] { $bits } бит
    [few] { $bits } бита
   *[many] { $bits } бит
}), диапазон { $range }
k2-help-area = { $unit ->
    [elements] область { $area } ({ $meaning }): { $n ->
        [one] { $n } элемент
        [few] { $n } элемента
       *[many] { $n } элементов
    } на { $model }
   *[bytes] область { $area } ({ $meaning }): { $n ->
        [one] { $n } байт
        [few] { $n } байта
       *[many] { $n } байт
    } на { $model }
}
k2-help-manual = руководство { $section }
k2-help-source = источник: { $source }
k2-help-written-as = записан так, как операнды пишут руководство и KincoBuilder (в стиле S7-200)
k2-complete-form = { $form ->
    [I] бит входа I0.0
    [IB] байт входов
    [Q] бит выхода Q0.0
    [QB] байт выходов
    [M] бит M0.0
    [MB] байт M
    [MW] слово M
    [MD] двойное слово M
    [V] бит V0.0
    [VB] байт V
    [VW] слово V
    [VD] двойное слово V
    [SM] область SM
    [AIW] слово аналогового входа
    [AQW] слово аналогового выхода
    [T] таймер
    [C] счетчик
   *[K4M] 16-битная группа битов M
}

## Снимки симуляторов (snapshot)

snapshot-cannot-encode = не удаётся закодировать снимок
snapshot-section-invalid = раздел { $section } устройства `{ $device }` в снимке неверен
snapshot-section-invalid-at = раздел { $section } устройства `{ $device }` в снимке неверен в `{ $at }`
snapshot-file-damaged = возможно, файл повреждён
snapshot-wire-of = соединение `{ $name }` в снимке
snapshot-cannot-snapshot = нельзя сделать снимок `{ $name }`: { $why }
snapshot-all-or-none = снимок содержит все симулируемые устройства или ни одного
snapshot-family-not-kept = нельзя сделать снимок `{ $name }`: состояние симулятора { $family } в снимках не сохраняется
snapshot-family-not-kept-hint = закройте его перед сохранением или сохраните без него
snapshot-nothing = ни один симулятор не открыт: снимать нечего
snapshot-nothing-hint = снимки содержат состояние симуляторов (sim:MODEL, sim-servo:, sim-fx:, sim-umpk:); состояние реального устройства хранится в нём самом
snapshot-has-device = в снимке есть это устройство
snapshot-not-simulated = `{ $name }` — не симулятор { $family }, каким он был при сохранении снимка
snapshot-not-simulated-hint = откройте те же симуляторы под теми же именами (например, --device plc=sim:MODEL)
snapshot-model-differs = { $article ->
    [an] нельзя восстановить `{ $name }`: снимок сделан с { $saved }, а этот симулятор — { $model }
   *[a] нельзя восстановить `{ $name }`: снимок сделан с { $saved }, а этот симулятор — { $model }
}
snapshot-open-as = откройте его как { $name }={ $scheme }:{ $model }
snapshot-restoring-wire = восстановление соединения `{ $wire }` устройства `{ $name }`
snapshot-cannot-restore = нельзя восстановить `{ $name }`: { $why }
snapshot-wires-not-back = восстановление `{ $name }`: его соединения не восстановились такими, как были сохранены
snapshot-not-format = это не снимок plcsh (формат `{ $format }`)
snapshot-newer-version = снимок версии { $version }, этот plcsh читает версии до { $max }
snapshot-newer-version-hint = восстановите его более новым plcsh, которым он сохранён
snapshot-unknown-section = у `{ $name }` в снимке есть раздел `{ $section }`, который этот plcsh восстановить не может
snapshot-unknown-section-hint = снимок сохранён более новым plcsh; восстановление без этого раздела не даст того же состояния
snapshot-save-refused = нельзя сохранить снимок: { $why }
snapshot-save-refused-hint = ничего не записано: файл не восстановился бы. Это ошибка plcsh; сообщите о ней вместе с командами, которые к ней привели
snapshot-does-not-read-back = он не читается обратно ({ $error })
snapshot-section-changes = раздел { $section } устройства `{ $name }` не читается обратно таким, как сохранён: `{ $at }` меняется
snapshot-cannot-read = не удаётся прочитать снимок { $path }
snapshot-cannot-read-hint = сохранённые снимки перечисляет `sim snapshots`
snapshot-not-snapshot = { $path } — не снимок plcsh
snapshot-no-k2 = в снимке нет симулятора K2

## Соединения между симулируемыми устройствами (core::wiring, wiring)

wire-not-terminal = `{ $text }` — не клемма: пишите УСТРОЙСТВО:КЛЕММА
wire-no-device-or-terminal = в `{ $text }` нет устройства или клеммы
wire-not-wire = `{ $text }` — не соединение: пишите ОТКУДА -> КУДА
wire-not-wire-hint = например, sim wire plc:Q0.0 -> servo:pulse
wire-no-destination = у соединения нет цели после `->`
wire-options-key-value = `{ $word }`: параметры соединения пишутся как ключ=значение
wire-options-short-hint = параметры: lines=N (энкодер), delay=D (обратная петля)
wire-lines-positive = lines={ $value }: число линий на оборот должно быть целым положительным
wire-delay-negative = delay={ $value } отрицательна
wire-delay-too-long = delay={ $value } больше, чем вмещает соединение: не больше { $max } мкс (около 584 лет)
wire-no-option = у соединений нет параметра `{ $key }`
wire-options-hint = параметры: lines=N (выход энкодера), delay=D (с выхода на вход)
wire-cannot-join = { $from } нельзя соединить с { $to }
wire-cannot-join-hint = возможные соединения: импульсный выход ПЛК -> servo:pulse; servo:encoder -> два входа ПЛК (A,B); servo:target_reached|fault|enabled -> вход ПЛК; servo:home@POS|limit+@POS|limit-@POS -> вход ПЛК; выход ПЛК -> вход ПЛК [delay=D]
wire-lines-encoder-only = lines= относится к выходу энкодера (servo:encoder -> …)
wire-delay-loop-only = delay= относится к выходу ПЛК, соединённому с входом ПЛК
wire-not-position = { $terminal }: `{ $text }` — не позиция в инкрементах
wire-only-switches-at = { $terminal }: @POS принимают только выключатели home, limit+ и limit-
wire-unknown-drive-terminal = клемма сервопривода `{ $name }` неизвестна ({ $terminal })
wire-drive-terminals-hint = клеммы сервопривода: pulse, encoder, target_reached, fault, enabled, home@POS, limit+@POS, limit-@POS
wire-describe-pulses = импульсы PTO{ $channel } (с выходом направления) на импульсный вход
wire-describe-encoder-lines = энкодер A/B, { $lines ->
    [one] { $lines } линия
    [few] { $lines } линии
   *[many] { $lines } линий
} (периодов A/B) на оборот
wire-describe-encoder = энкодер A/B, четверть периода на инкремент
wire-describe-drive-output = { $output ->
    [target-reached] выход сервопривода: заданное положение достигнуто (бит 10 слова состояния)
    [fault] выход сервопривода: неисправность
   *[enabled] выход сервопривода: работа разрешена
}
wire-describe-switch = выключатель { $switch } в позиции { $position } инкрементов (также собственный вход сервопривода)
wire-describe-loop = с выхода на вход, задержка { $delay } мкс
wire-describe-pulse-loop = выход PTO{ $channel } (импульсы и уровень) на вход, задержка { $delay } мкс
wire-real-plc = { $name } — реальный ПЛК: соединения связывают симулируемые устройства
wire-real-plc-hint = откройте симулятор, например connect plc sim:K205-16DT
wire-real-drive = { $name } — реальный сервопривод: соединения связывают симулируемые устройства
wire-real-drive-hint = откройте симулятор сервопривода, например connect servo sim-servo:?id=1
wire-cannot-wire = { $name } нельзя соединять (только симуляторы ПЛК K2 и сервоприводов)
wire-two-plcs = { $wire }: соединения между двумя ПЛК не симулируются; выход ПЛК соединяется только с его собственными входами
wire-two-drives = { $wire }: соединения между сервоприводами не симулируются
wire-two-drives-hint = соединяйте сервоприводы с симулятором ПЛК
wire-nothing = соединений нет
wire-nothing-hint = sim wire ОТКУДА -> КУДА добавляет соединение, например sim wire plc:Q0.0 -> servo:pulse

## Стенды: симулируемая установка из файла (wiring::bench)

bench-no-faults = { $device } не принимает внесённые неисправности (их принимают только симуляторы ПЛК K2 и сервоприводов)
bench-shape-hint = в стенде есть [devices] ИМЯ = "URL" и, по желанию, wires = ["A -> B"], init = ["DEV:OP=VALUE"], [programs], [tags], [[faults]]
bench-no-devices = стенд { $file }: раздел [devices] пуст
bench-cannot-read = не удаётся прочитать файл стенда { $file }
bench-not-simulator = стенд { $file }: устройство { $name } = { $url } — не симулятор
bench-not-simulator-hint = файл стенда описывает симулируемую установку: используйте sim:MODEL и sim-servo:?id=N
bench-at-device = стенд { $file }, устройство { $name }
bench-at-wire = стенд { $file }, соединение { $n } `{ $wire }`
bench-at-init = стенд { $file }, init { $n } `{ $item }`
bench-at-fault = стенд { $file }, неисправность { $n } `{ $fault }`
bench-at-program = стенд { $file }, программа для { $device }
bench-init-shape = стенд { $file }, init { $n }: `{ $item }` не в виде DEVICE:OPERAND=VALUE
bench-fault-on = неисправность на { $device }: { $what }
bench-program-missing = стенд { $file }: программы { $program } для { $device } не существует
bench-program-unreadable = стенд { $file }: не удаётся прочитать программу { $program }: { $error }
bench-program-not-k2 = стенд { $file }: программа выполняется в симуляторе K2, а { $device } — не он
bench-program-not-k2-hint = задавайте программы только для устройств sim:MODEL
bench-opened = стенд { $name }: устройств: { $devices }, соединений: { $wires }, значений: { $values }
bench-second-plc = стенд { $file }: { $name } — второй ПЛК; sim serve обслуживает один ПЛК
bench-second-line = стенд { $file }: { $name } на второй линии сервоприводов; sim serve обслуживает одну линию
bench-second-line-hint = поместите сервоприводы на одну линию: sim-servo:axis?id=1 и sim-servo:axis?id=2

## PLS в симуляторе: что запускается и почему отказ (k2::sim::pto; руководство §3.4.2)

k2-pls-refused = PLS { $channel }: { $reason }; бит состояния SM{ $byte }.4 установлен
k2-pls-pwm-cycle-below-two = время цикла PWM { $cycle } меньше 2
k2-pls-pwm-cycle-below-two-hint = задайте SMW{ $register } (2…65535) и бит обновления SM{ $control }.0, затем снова PLS
k2-pls-cycle-below-two = время цикла { $cycle } меньше 2 (время цикла и количество импульсов должны быть больше 1, §3.4.2.2)
k2-pls-cycle-below-two-hint = загрузите SMW{ $register } с установленным SM{ $control }.0 (например, SMB{ $control }=16#85), затем снова PLS
k2-pls-count-below-two = количество импульсов { $count } меньше 2 (время цикла и количество импульсов должны быть больше 1, §3.4.2.2)
k2-pls-count-below-two-hint = загрузите SMD{ $register } с установленным SM{ $control }.2 (например, SMB{ $control }=16#85), затем снова PLS
k2-pls-what-cycle = время цикла { $cycle } { $unit }
k2-pls-what-segment-cycle = время цикла сегмента { $n } { $cycle } { $unit }
k2-pls-too-fast = { $what } — это { $hz } Гц, выше предела { $output } на этой модели, { $max } Гц (руководство §3.4)
k2-pls-did-nothing = PLS { $channel } ничего не сделала: в байте управления SMB{ $control } = 16#{ $value } бит включения SM{ $control }.7 сброшен, а PTO{ $channel } ({ $output }) в режиме ожидания
k2-pls-stopped = { $name } остановлен ({ $what }; бит включения SM{ $control }.7 равен 0)
k2-pls-pwm-started = { $update ->
    [sync] { $name }: PWM, время цикла { $cycle } { $unit }, длительность импульса { $width } { $unit } ({ $duty } %), синхронное обновление
   *[async] { $name }: PWM, время цикла { $cycle } { $unit }, длительность импульса { $width } { $unit } ({ $duty } %)
}
k2-pls-pto-started = { $name }: { $pulses ->
    [one] { $pulses } импульс
    [few] { $pulses } импульса
   *[many] { $pulses } импульсов
} в { $segments ->
    [one] { $segments } сегменте
   *[other] { $segments } сегментах
}, { $seconds } с
k2-pls-table-even = начало таблицы профиля SMW{ $register } = { $start } — чётное
k2-pls-table-even-hint = таблица должна начинаться с нечётного адреса V, например SMW{ $register }=3001 для VB3001 (§3.4.2.1)
k2-pls-table-past-v = начало таблицы профиля VB{ $start } за пределами области V (VB{ $top })
k2-pls-table-past-v-hint = укажите нечётный адрес внутри области V
k2-pls-table-segments = таблица профиля в VB{ $start } содержит { $n ->
    [one] { $n } сегмент
    [few] { $n } сегмента
   *[many] { $n } сегментов
} (допустимо 1–{ $max })
k2-pls-table-segments-hint = запишите число сегментов в первый байт таблицы
k2-pls-table-runs-past = таблица профиля VB{ $start }…VB{ $last } выходит за конец области V
k2-pls-table-runs-past-hint = перенесите таблицу или уменьшите число сегментов
k2-pls-segment-cycle = время цикла сегмента { $n } VW{ $word } = { $cycle } меньше 2
k2-pls-segment-cycle-hint = время цикла — от 2 до 65535 во временной базе канала
k2-pls-segment-count = количество импульсов сегмента { $n } VD{ $dword } равно 0
k2-pls-segment-count-hint = каждому сегменту нужен хотя бы 1 импульс
k2-pls-other-channel-hint = установлен SMB{ $control } = 16#{ $value }: это байт управления PTO{ $channel } ({ $output }) — может быть, имелась в виду PLS { $channel }?
k2-pls-set-control-hint = сначала задайте байт управления, например set SMB{ $control }=16#85, SMW{ $cycle }=500, SMD{ $count }=1000
k2-pstop = { $what ->
    [none] PSTOP { $channel }: ничего не работало; бит аварийного останова SM{ $byte }.7 = 1 (сбросьте его: set SM{ $byte }.7=0)
   *[other] PSTOP { $channel }: { $what } остановлен; бит аварийного останова SM{ $byte }.7 = 1 (сбросьте его: set SM{ $byte }.7=0)
}

## Симулятор K2: входы, сохранение данных, параметры, внесённые неисправности (k2::sim)

k2-input-driven = { $pin } управляется симулируемым сигналом ({ $source })
k2-input-driven-by-wire-hint = его ведёт соединение: sim unwire plc:{ $pin }
k2-input-driven-hint = сначала остановите его: sim input { $pin } off
k2-input-counted-by = считается HSC{ $n } (режим { $mode })
k2-input-above-hsc-limit = внимание: выше предела HSC{ $n } { $max } Гц на { $model } (§3.3): реальный ПЛК пропустит импульсы
k2-input-no-source = { $pin } не управляется симулируемым сигналом
k2-input-no-source-hint = `sim inputs` перечисляет источники
k2-retain-area = { $part }: сохраняться могут только диапазоны V, M и C
k2-retain-area-hint = например, sim retain VB0..VB99 MB0[16] C0..C15
k2-retain-too-much = запрошено { $bytes } байт сохранения данных; { $model } сохраняет не больше { $room } (руководство §2.1.2)
k2-retain-too-much-hint = сохраняйте меньше или более короткие диапазоны (счетчик занимает 2 байта)
k2-state-not-saved = состояние симулятора не сохранено: { $error }
k2-fault-exception = ПЛК отклонил запрос: исключение Modbus { $code } { $name } (внесённая неисправность { $id })
k2-fault-no-power = нет ответа от ПЛК: у него нет питания (внесённая неисправность { $id })
k2-fault-no-power-hint = sim faults показывает, когда вернётся питание; sim fault clear возвращает его сразу
k2-fault-no-reply = нет ответа от ПЛК (внесённая неисправность { $id }: { $name })
k2-fault-no-reply-hint = sim faults перечисляет внесённые неисправности; sim fault clear убирает их
k2-option-backup-last = backup_last={ $value } — не адрес байта V
k2-option-program-unreadable = не удаётся прочитать программу { $file }: { $error }
k2-option-unknown = у симуляторов K2 нет параметра `{ $key }`
k2-sim-relay-model = у { $model } релейные выходы: импульсных выходов PTO/PWM нет (руководство §2.2.6)
k2-sim-no-pulse-channel-q05 = у { $model } нет импульсного канала { $channel } (Q0.5 — импульсный выход только у K209M-56DT)
k2-sim-pulse-channels-hint = импульсные каналы { $model }: { $list }

## Внесённые неисправности симулятора K2 (k2::sim::fault, k2::sim::control)

k2-fault-negative = { $key }={ $value }: не может быть отрицательным
k2-fault-not-input = `{ $text }` — не бит входа (например, I0.1)
k2-fault-which = какая неисправность? { $usage }
k2-fault-needs-code = `{ $kind }` нужен код (1…255, например 2 — недопустимый адрес данных)
k2-fault-not-code = `{ $code }` — не код исключения Modbus (1…255)
k2-fault-needs-delay = `{ $kind }` нужна задержка (например, late 300ms)
k2-fault-needs-input-level = `{ $kind }` нужны вход и уровень (stuck I0.1=1)
k2-fault-stuck-shape = `{ $word }`: пишите stuck I0.1=1 или stuck I0.1=0
k2-fault-not-level = `{ $value }` — не уровень (0 или 1)
k2-fault-needs-input = `{ $kind }` нужен вход (noisy I0.1 freq=5kHz)
k2-fault-not-kind = `{ $kind }` — не вид неисправности; { $usage }
k2-fault-on-needs-operands = `on` нужны операнды, например on VW100..VW110
k2-fault-spans-areas = `{ $operands }` охватывает несколько областей: укажите диапазон одной области
k2-fault-not-option = `{ $word }` — не параметр; { $usage }
k2-fault-times = times={ $value }: число от 1
k2-fault-freq-noisy-only = freq= — только для зашумлённых входов
k2-fault-unknown-option = неизвестный параметр `{ $key }=`; { $usage }
k2-fault-noisy-needs-freq = зашумлённому входу нужен freq= (сколько случайных уровней в секунду), например freq=5kHz
k2-fault-at-or-after = укажите at= или after=, но не оба
k2-fault-power-loss-needs-for = пропаданию питания нужна длительность: power-loss for=5s (после неё ПЛК снова работает)
k2-fault-power-loss-options = пропадание питания принимает at=, after= и for= (оно действует на весь ПЛК)
k2-fault-on-request-only = `on` — для неисправностей запросов; { $kind } называет свой вход
k2-control-words-hint = управляющие слова: { $words }; неисправности: { $usage }
k2-control-acts-when-served = (действует, когда симулятор обслуживается: sim serve --fault … или его канал управления)
k2-control-empty = пустая строка управления
k2-control-unknown-word = `{ $word }` — не управляющее слово симулятора K2

## Драйвер линии K2: ответы Modbus и почтовый ящик помощника (k2::driver)

k2-reply-bad-crc = пришёл ответ с неверной контрольной суммой CRC: { $frame } (CRC { $got }, для этих байт нужна { $want })
k2-reply-bad-crc-received = пришёл ответ с неверной контрольной суммой CRC: { $frame } (CRC { $got }, для этих байт нужна { $want }); принято: { $received }
k2-reply-no-frame = пришло байт: { $n }, но ни одного верного кадра ответа; принято: { $received }
k2-not-k2-request = { $request } — не запрос к K2
k2-reply-function-code = ответ с кодом функции { $got } на запрос с кодом { $want }
k2-reply-unit = ответ от устройства { $got } на запрос к устройству { $want }
k2-reply-not-tcp = заголовок ответа не Modbus TCP: { $header }
k2-reply-transaction = ответ для транзакции { $tid }, устройства { $unit } на транзакцию { $want_tid }, устройство { $want_unit }
k2-no-more-replies = ответов больше нет
k2-reply-malformed = искажённый ответ на { $request }: { $data }
k2-reply-read-short = ответ на чтение { $table } { $addr } слишком короткий
k2-mailbox-refused = { $doing ->
    [reading] ПЛК отказал в чтении почтового ящика помощника: { $name } (исключение Modbus { $code })
   *[writing] ПЛК отказал в записи почтового ящика помощника: { $name } (исключение Modbus { $code })
}
k2-mailbox-refused-hint-2 = проверьте, что agent=VB… лежит внутри области V этой модели
k2-mailbox-refused-hint-4 = ПЛК сообщает о неисправности устройства: проверьте светодиод ошибки и диагностику, затем повторите
k2-mailbox-refused-hint = проверьте, что это порт Modbus и адрес ПЛК (plcsh probe URL покажет, что он отвечает)
k2-mailbox-unexpected-reply = неожиданный ответ { $reply } при чтении почтового ящика помощника
k2-needs-helper = { $what } требует программу-помощник plcsh в ПЛК; у этого устройства она не настроена
k2-needs-helper-hint = установите lib/k2_agent.il (docs/agent.md) и подключайтесь с …&agent=VB3400
k2-no-helper = у этого устройства помощник не настроен
k2-no-helper-hint = подключайтесь с …&agent=VB3400
k2-helper-status = протокол помощника { $version } в VB{ $base }, счётчик жизни { $heartbeat }, последняя команда { $seq } (результат { $result })
k2-done-by-helper = { $what }: выполнено помощником
k2-rtc-reply-short = ответ помощника на READ_RTC короче 8 байт
k2-rtc-reads-as = часы реального времени ПЛК читаются как { $value }

## Высокоскоростные счетчики в симуляторе: HDEF, HSC, таблицы PV (k2::sim::hsc; руководство §3.3)

k2-hsc-table-even = начало таблицы PV { $start } — чётное (это должно быть нечётное смещение в области V, §3.3.2)
k2-hsc-table-past-v = начало таблицы PV VB{ $start } за пределами области V
k2-hsc-table-count = таблица PV в VB{ $start } содержит { $n } PV (допустимо 1–{ $max })
k2-hsc-table-runs-past = таблица PV в VB{ $start } выходит за конец области V
k2-hsc-table-empty = таблица PV в VB{ $start } заканчивается до первого PV (|PV| должно быть > 1)
k2-hsc-no-mode-yet = у HSC{ $n } ещё нет режима
k2-hsc-no-mode-yet-hint = сначала выполните `hdef { $n } MODE` (HDEF, руководство §3.3.5); режимы: { $list }
k2-hsc-stopped = HSC{ $n } остановлен (бит включения SM{ $control }.7 равен 0); CV { $cv }
k2-hsc-table-fault = неисправность таблицы PV (SM{ $status }.3 = 1): { $reason }
k2-hsc-table-fault-none = неисправность таблицы PV (SM{ $status }.3 = 1): таблица не загружена; установите SM{ $mpv }.4, чтобы загрузить таблицу из SMW{ $table }
k2-hsc-counting-table = { $kind ->
    [relative-cyclic] относительных PV: { $n } (циклически), следующее CV = PV при { $target }
    [relative] относительных PV: { $n }, следующее CV = PV при { $target }
    [absolute-cyclic] абсолютных PV: { $n } (циклически), следующее CV = PV при { $target }
   *[absolute] абсолютных PV: { $n }, следующее CV = PV при { $target }
}
k2-hsc-counting-no-table = таблицы PV нет
k2-hsc-counting = HSC{ $n } считает в режиме { $mode } от CV { $cv }; { $compare }

## Файл состояния симулятора (k2::sim::state)

k2-backup-end = область резервного копирования данных E2PROM заканчивается на VB{ $default } (по умолчанию) … VB{ $max }, а не на VB{ $last }
k2-backup-end-hint = руководство §2.2.8: VB3648–VB3902 по умолчанию, расширяется до VB4095
k2-state-invalid = файл состояния { $file } неверен
k2-state-invalid-hint = уберите его, чтобы начать с чистого состояния
k2-state-unreadable = не удаётся прочитать файл состояния { $file }
k2-state-cannot-encode = не удаётся закодировать состояние
k2-state-in-use = файл состояния { $file } занят другим процессом
k2-state-in-use-by = файл состояния { $file } занят процессом { $pid }
k2-state-in-use-hint = один plcsh на файл состояния: дайте этому свой (--state FILE) или никакого (--state none), либо остановите другой

## Соединения на клеммах ПЛК, точки останова (k2::sim::wired, k2::sim::program::debug)

wire-not-plc-terminal = { $model }: `{ $terminal }` — не клемма ПЛК
wire-plc-terminals-hint = клеммы ПЛК: Q0.0 (выход), Q0.0,Q0.2 (импульсы + направление), I0.3 (вход), I0.1,I0.0 (A,B)
wire-no-pulse-output = у { $model } нет импульсного выхода на { $pin }
wire-no-pulse-output-hint = пара «импульсы + направление» начинается с выхода PTO (Q0.0 PTO0, Q0.1 PTO1 …)
wire-a-b-same = A и B — оба { $pin }
wire-ends = { $wire }: оба конца на одном устройстве, или ни один не на ПЛК
wire-ends-hint = соединяйте клемму ПЛК с клеммой сервопривода или выход ПЛК со входом ПЛК
wire-nothing-short-hint = sim wire ОТКУДА -> КУДА добавляет соединение
wire-none-touches = ни одно соединение не касается `{ $which }`
wire-list-hint = соединения: { $list }
k2-no-program = программа не загружена
k2-no-program-hint = sim program load FILE.il
k2-no-network = в { $source } нет сегмента { $n }
k2-no-network-hint = сегменты нумеруются комментариями `(* Network n *)` или строками NETWORK
k2-not-breakpoint = `{ $spec }` — не точка останова
k2-no-instruction-after = в { $source } нет инструкции на строке { $line } или после неё
k2-breakpoint-at = точка останова в { $source }:{ $line }: { $text }

## События, часы и операции, которых нет у подключения (k2::instr, k2)

k2-event-pto-complete = PTO{ $channel } завершён
k2-event-cv-eq-pv-multi = HSC{ $channel } CV = PV{ $k } (несколько PV)
k2-event-cv-eq-pv = HSC{ $channel } CV = PV (одно PV)
k2-event-hsc-reset = внешний сброс HSC{ $channel }
k2-event-hsc-direction = { $dir ->
    [up] направление счета HSC{ $channel } сменилось на счёт вверх
   *[down] направление счета HSC{ $channel } сменилось на счёт вниз
}
k2-event-eeprom-wear = байт E2PROM VB{ $byte } записан { $writes ->
    [one] { $writes } раз
    [few] { $writes } раза
   *[many] { $writes } раз
} (ресурс ~1 000 000, §2.2.8)
k2-event-fault = сработала внесённая неисправность { $id } ({ $name })
k2-rtc-not-datetime = `{ $text }` — не дата и время; пишите так: 2026-11-22T10:00:00
k2-rtc-year = год { $year } вне 2000–2099 (часы хранят две цифры)
k2-rtc-month = месяц { $month } не в 1–12
k2-rtc-day = день { $day } не в 1–{ $days } для { $month }
k2-rtc-time = { $time } — не время суток
k2-rtc-not-bcd = 16#{ $value } — не байт BCD
k2-what-event-access = доступ к событиям
k2-what-helper-status = состояние помощника
k2-not-here = { $what }: недоступно на этом подключении
k2-not-here-hint = симулятор это выполняет; на реальном ПЛК нужна программа-помощник на стороне ПЛК
k2-no-longer-k2 = устройство больше не отвечает как ПЛК K2
snapshot-not-name = `{ $name }` — не имя снимка (латинские буквы A-Z a-z, цифры, _ - .)
snapshot-not-name-hint = или укажите путь к файлу, оканчивающийся на .json
snapshot-no-data-dir = нет каталога данных для снимков
snapshot-no-data-dir-hint = укажите путь к файлу, оканчивающийся на .json

## Операнды и инструкции программы IL в симуляторе K2 (k2::sim::program)

k2-program-one-location = операнд программы — одно место, а не диапазон
k2-program-bit-group = { $operand } — группа битов; программы обращаются к байтам, словам и битам
k2-program-bit-group-hint = используйте в программах слова MW/VW или биты M/V
k2-program-not-element = { $what ->
    [timer] { $operand } — не таймер
   *[counter] { $operand } — не счетчик
}
k2-program-timers-hint = таймеры: T0…T255
k2-program-counters-hint = счетчики: C0…C255
k2-program-clock-buffer = 8-байтовый буфер часов туда не помещается
k2-program-unknown-instruction = неизвестная инструкция семейства { $id }

## Восстановление симулятора K2 из снимка (k2::sim::snapshot)

k2-snapshot-model = снимок сделан с { $saved }, а этот симулятор — { $model }
k2-snapshot-area-hex = область { $area } не в шестнадцатеричном виде
k2-snapshot-area-size = в области { $area } { $n ->
    [one] { $n } байт
    [few] { $n } байта
   *[many] { $n } байт
}, а у { $model } — { $want }
k2-snapshot-element-counts = число таймеров или счетчиков отличается от модели
k2-snapshot-channel-counts = число импульсных выходов или счетчиков отличается от модели
k2-snapshot-no-area = нет области { $area }
k2-snapshot-helper-program = программа-помощник: { $error }
k2-snapshot-program = программа снимка { $source }: { $error }
k2-snapshot-halt = останов DEBUG в снимке на инструкции { $at }, а в программе их { $n }
k2-snapshot-breakpoint = точка останова в снимке на инструкции { $at }, а в программе их { $n }

## Симулируемые входные сигналы, почтовый ящик помощника, обслуживаемый симулятор (k2::sim)

k2-hsc-snapshot-mode = у HSC{ $n } нет режима { $mode }
k2-source-square = { $pin }: меандр { $freq }
k2-source-quadrature = квадратурный сигнал A/B: { $lead } опережает { $lag }, { $freq }
k2-source-train = { $pin }: последовательность импульсов, { $pulses ->
    [one] { $pulses } импульс
    [few] { $pulses } импульса
   *[many] { $pulses } импульсов
} по { $cycle } нс
k2-source-encoder = энкодер: A на { $a }, B на { $b }
k2-helper-mailbox-address = почтовому ящику помощника нужен чётный адрес V, от которого свободно { $size } байт до VB{ $top } (получен VB{ $base })
k2-serve-accept-retry = сейчас не удаётся принять соединение ({ $error }); повтор
k2-serve-stream-closed = поток закрыт
