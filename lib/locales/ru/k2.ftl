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
