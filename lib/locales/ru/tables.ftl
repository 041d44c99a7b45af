# plcsh messages (ru): tables — описания байтов SM, объектов сервопривода, инструкций и элементов. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## K2 special memory (src/k2/sm_map.rs; K2 manual §3.3.2, §3.3.3, §3.4.2.2, §3.4.3.1)

tbl-sm-pos-cv-read-only = SMD{ $cv } — текущее значение канала позиционирования { $n }, только для чтения (руководство §3.4.3.1)
tbl-sm-pos-cv-overlap = { $written } перекрывает SMD{ $cv } — текущее значение канала позиционирования { $n }, только для чтения (руководство §3.4.3.1)
tbl-sm-pos-cv-read-only-hint = загрузите новое значение через SMD{ $new } и SM{ $control }.4 (set SMD{ $new }=100, SM{ $control }.4=1) или сбросьте его битом SM{ $control }.6
tbl-sm-pls-did-nothing = PLS { $n } ничего не сделала: бит включения SM{ $control }.7 контрольного байта SMB{ $control } сброшен, и PTO{ $n } в режиме ожидания
tbl-sm-pls-did-nothing-hint = установите SMB{ $control }=16#85 (включить, PTO, обновить время цикла и количество импульсов), SMW{ $cycle } и SMD{ $count }, затем PLS { $n }
tbl-sm-smb0-read-only = { $written } хранит системные биты состояния и доступен только для чтения
tbl-sm-smb0-read-only-hint = SM0.0 всегда включён, SM0.1 — первое сканирование, SM0.5 — секундный такт
tbl-hsc-mode-0-0 = счёт I0.1, направление счета по SM37.3
tbl-hsc-mode-0-1 = счёт I0.1, сброс I0.0, направление счета по SM37.3
tbl-hsc-mode-0-2 = счёт I0.1, сброс I0.0, пуск I0.5, направление счета по SM37.3
tbl-hsc-mode-0-3 = счёт I0.1, вход направления I0.5
tbl-hsc-mode-0-4 = счёт I0.1, вход направления I0.5, сброс I0.0
tbl-hsc-mode-0-6 = счёт вверх I0.0 / счёт вниз I0.1 (двухфазный)
tbl-hsc-mode-0-9 = фаза AB, A = I0.1, B = I0.0
tbl-hsc-mode-1-0 = счёт I0.3, направление счета по SM47.3
tbl-hsc-mode-1-1 = счёт I0.3, сброс I0.4, направление счета по SM47.3
tbl-hsc-mode-1-2 = счёт I0.3, сброс I0.4, пуск I0.6, направление счета по SM47.3
tbl-hsc-mode-1-3 = счёт I0.3, вход направления I0.2
tbl-hsc-mode-1-4 = счёт I0.3, вход направления I0.2, сброс I0.4
tbl-hsc-mode-1-6 = счёт вверх I0.2 / счёт вниз I0.3 (двухфазный)
tbl-hsc-mode-1-7 = счёт вверх I0.2 / счёт вниз I0.3 (двухфазный), сброс I0.4
tbl-hsc-mode-1-9 = фаза AB, A = I0.3, B = I0.2
tbl-hsc-mode-1-10 = фаза AB, A = I0.3, B = I0.2, сброс I0.4
tbl-hsc-mode-2-0 = счёт I0.5, направление счета по SM57.3
tbl-hsc-mode-2-9 = фаза AB, A = I0.4, B = I0.5
tbl-hsc-mode-3-0 = счёт I0.7, направление счета по SM127.3
tbl-hsc-mode-3-9 = фаза AB, A = I0.6, B = I0.7
tbl-sm-smb0 = системные биты состояния (только для чтения)
tbl-sm-sm0-0 = всегда включён
tbl-sm-sm0-1 = включён только в первом сканировании
tbl-sm-sm0-5 = секундный такт (0,5 с включён, 0,5 с выключен)
tbl-sm-sm0-6 = переключается каждое сканирование
tbl-sm-pto-control = контрольный байт PTO{ $n }/PWM{ $n } ({ $q })
tbl-sm-pto-control-0 = управление PTO{ $n }: обновлять время цикла
tbl-sm-pto-control-1 = управление PTO{ $n }: обновлять длительность импульса (PWM)
tbl-sm-pto-control-2 = управление PTO{ $n }: обновлять количество импульсов (PTO)
tbl-sm-pto-control-3 = управление PTO{ $n }: база времени: 0 = 1 мкс, 1 = 1 мс
tbl-sm-pto-control-4 = управление PTO{ $n }: метод обновления PWM: 0 асинхронный, 1 синхронный
tbl-sm-pto-control-5 = управление PTO{ $n }: режим работы PTO: 0 односегментный, 1 многосегментный
tbl-sm-pto-control-6 = управление PTO{ $n }: выбор функции: 0 PTO, 1 PWM
tbl-sm-pto-control-7 = управление PTO{ $n }: включение
tbl-sm-pto-status = байт состояния PTO{ $n }/PWM{ $n } ({ $q })
tbl-sm-pto-status-3 = состояние PTO{ $n }: PWM в режиме ожидания
tbl-sm-pto-status-4 = состояние PTO{ $n }: время цикла или количество импульсов неверное (должно быть больше 1)
tbl-sm-pto-status-5 = состояние PTO{ $n }: профиль прекращён командой пользователя
tbl-sm-pto-status-7 = состояние PTO{ $n }: PTO в режиме ожидания
tbl-sm-pto-cycle = время цикла PTO{ $n }/PWM{ $n } (2…65535, в единицах базы времени)
tbl-sm-pwm-width = длительность импульса PWM{ $n } (0…65535, в единицах базы времени)
tbl-sm-pto-count = количество импульсов PTO{ $n } (≥ 2)
tbl-sm-pto-profile = начало таблицы профиля многосегментного PTO{ $n } (нечетное смещение в области V)
tbl-sm-pos-cv = текущее значение канала позиционирования { $n }, импульсы (только для чтения)
tbl-sm-pos-new-cv = новое текущее значение канала позиционирования { $n } (загружается битом 4 байта SMB{ $control })
tbl-sm-pos-control = управляющий байт канала позиционирования { $n }
tbl-sm-pos-control-7 = управление каналом позиционирования { $n }: бит аварийного останова (устанавливается PSTOP)
tbl-sm-pos-control-6 = управление каналом позиционирования { $n }: сброс текущего значения
tbl-sm-pos-control-4 = управление каналом позиционирования { $n }: загрузить новое текущее значение
tbl-sm-pos-control-3 = управление каналом позиционирования { $n }: отключить выходной канал направления
tbl-sm-hsc-control = байт управления HSC{ $n }
tbl-sm-hsc-control-0 = управление HSC{ $n }: эффективный уровень сигнала сброса (0 высокий, 1 низкий)
tbl-sm-hsc-control-1 = управление HSC{ $n }: эффективный уровень сигнала старта (0 высокий, 1 низкий)
tbl-sm-hsc-control-2 = управление HSC{ $n }: фаза AB, умножение (0 = на 1, 1 = на 4)
tbl-sm-hsc-control-3 = управление HSC{ $n }: направление счета (0 вниз, 1 вверх)
tbl-sm-hsc-control-4 = управление HSC{ $n }: записать направление счета
tbl-sm-hsc-control-5 = управление HSC{ $n }: записать новое заданное значение
tbl-sm-hsc-control-6 = управление HSC{ $n }: записать новое текущее значение
tbl-sm-hsc-control-7 = управление HSC{ $n }: разрешить счетчик
tbl-sm-hsc-status = байт состояния HSC{ $n }
tbl-sm-hsc-status-3 = состояние HSC{ $n }: неисправность в таблице значений PV
tbl-sm-hsc-status-5 = состояние HSC{ $n }: текущее направление счета (1 вверх)
tbl-sm-hsc-status-6 = состояние HSC{ $n }: CV = PV
tbl-sm-hsc-status-7 = состояние HSC{ $n }: CV > PV
tbl-sm-hsc-cv = текущее значение HSC{ $n } (CV)
tbl-sm-hsc-pv = заданное значение HSC{ $n } (PV, режим одного PV)
tbl-sm-hsc-mpv-control = байт управления несколькими PV HSC{ $n }
tbl-sm-hsc-mpv-control-0 = управление несколькими PV HSC{ $n }: использовать несколько значений PV
tbl-sm-hsc-mpv-control-1 = управление несколькими PV HSC{ $n }: тип PV (0 абсолютное, 1 относительное)
tbl-sm-hsc-mpv-control-2 = управление несколькими PV HSC{ $n }: циклические прерывания CV=PV (только относительные)
tbl-sm-hsc-mpv-control-4 = управление несколькими PV HSC{ $n }: загрузить таблицу PV
tbl-sm-hsc-mpv-control-5 = управление несколькими PV HSC{ $n }: сброс переменной прерывания (0 да, 1 нет)
tbl-sm-hsc-table = начальный адрес таблицы PV HSC{ $n } (нечетное смещение в области V)
tbl-sm-hsc-segment = номер текущего сегмента PV HSC{ $n } (с 0)

## Servo object dictionary (src/servo/objects.rs; Kinco servo RS232 protocol, CiA 402)

tbl-servo-not-in-table = нет в таблице
tbl-servo-object-missing = не указан объект (например, controlword или 6040.00)
tbl-servo-not-a-type = `/{ $suffix }` — не тип объекта
tbl-servo-not-a-type-hint = используйте /u8, /i8, /u16, /i16, /u32 или /i32
tbl-servo-not-an-object = `{ $text }` — не объект сервопривода
tbl-servo-suffix-size = { $name } ({ $address }) занимает { $bits } бит; /{ $suffix } — { $suffix_bits } бит
tbl-servo-suffix-size-hint = уберите суффикс или используйте /{ $suffix }
tbl-servo-size-unknown = { $address } нет в таблице объектов, поэтому его размер неизвестен
tbl-servo-size-unknown-hint = добавьте суффикс типа, например { $address }/u16 (u8, i8, u16, i16, u32, i32)
tbl-servo-suggest-none = объекты перечисляют `help servo` и автодополнение; произвольный объект записывается как 6040.00
tbl-servo-suggest = возможно, имелось в виду { $names }?
tbl-servo-read-only = { $name } ({ $address }) только для чтения
tbl-servo-read-only-hint = прочитайте его командой get; привод ответил бы 0x80 (попытка записи в объект только для чтения)
tbl-servo-far-too-large = { $text } слишком велико для { $dtype } ({ $lo }…{ $hi })
tbl-servo-does-not-fit = { $text } = { $raw } не помещается в { $dtype } ({ $lo }…{ $hi })
tbl-servo-resolution-hint = разрешение энкодера — { $resolution } inc/об
tbl-servo-help-type = тип { $dtype } ({ $bits } бит), диапазон { $lo }…{ $hi }
tbl-servo-help-access = доступ { $access }
tbl-servo-help-access-unit = доступ { $access }, единица { $unit }
tbl-servo-help-access-unit-example = доступ { $access }, единица { $unit } (запись, например, { $name }=300{ $eng }; разрешение энкодера { $resolution } inc/об)
tbl-servo-help-source = источник: { $source }
tbl-servo-controlword = управляющее слово DS402: 0x06 выключение (shutdown), 0x07 включение (switch on), 0x0F разрешение работы (enable operation), бит 4 новое задание, бит 5 применить задание сразу, бит 6 относительное, бит 7 сброс неисправности, бит 8 остановка (halt), бит 12 — пуск Kinco при записи цели (0x103F)
tbl-servo-statusword = слово состояния DS402: биты состояния 0-6, бит 10 цель достигнута, бит 11 внутреннее ограничение, бит 12 задание принято / возврат в исходное положение выполнен, бит 13 ошибка рассогласования / ошибка возврата, бит 15 исходное положение Kinco найдено
tbl-servo-error-code = последний код ошибки (DS402; 0 = нет неисправности)
tbl-servo-quickstop-option = код реакции на быстрый останов: 0 выбег, 1/2 торможение с профильным / быстрым замедлением, затем «включение запрещено», 5/6 то же с переходом в «быстрый останов активен»
tbl-servo-shutdown-option = код реакции на выключение (сохраняется; симулятор останавливается сразу)
tbl-servo-disable-option = код реакции на запрет работы (сохраняется; симулятор останавливается сразу)
tbl-servo-halt-option = код реакции на остановку (halt): 1 торможение с профильным замедлением, 2 с замедлением быстрого останова
tbl-servo-fault-reaction-option = код реакции на неисправность (сохраняется; симулятор останавливается сразу)
tbl-servo-operating-mode = режим работы: 1 профильное позиционирование, 3 профильная скорость, -3 непосредственная скорость, 4 крутящий момент, 6 возврат в исходное положение, -4 импульсное задание
tbl-servo-mode-display = действующий режим работы (DS402; для Kinco не подтверждено)
tbl-servo-position-actual = фактическое положение (приводы Kinco используют 6063, а не 6064)
tbl-servo-position-actual-value = фактическое положение по нумерации DS402 (в симуляторе то же значение, что 6063; для Kinco не подтверждено)
tbl-servo-max-following-error = окно ошибки рассогласования: рассогласование больше него дольше 6066.00 вызывает неисправность привода (0x8611)
tbl-servo-following-error-timeout = тайм-аут ошибки рассогласования, мс
tbl-servo-position-window = окно положения для «цель достигнута»
tbl-servo-velocity-actual = фактическая скорость
tbl-servo-target-torque = заданный крутящий момент (единица не подтверждена)
tbl-servo-max-current = максимальное задание тока (единица не подтверждена)
tbl-servo-torque-actual = фактический крутящий момент (единица не подтверждена)
tbl-servo-current-actual = фактический ток (единица не подтверждена)
tbl-servo-target-position = заданное положение для режима профильного позиционирования
tbl-servo-home-offset = смещение исходного положения: положение, присваиваемое точке исходного положения после возврата
tbl-servo-soft-limit-pos = программный предел положения + (по notes и C#-клиенту; в CiA 402 субиндекс 1 — минимальный предел, проверьте свой привод); пределы отключены, пока + <= -
tbl-servo-soft-limit-neg = программный предел положения - (по notes и C#-клиенту; в CiA 402 субиндекс 2 — максимальный предел, проверьте свой привод)
tbl-servo-polarity = направление: 0 — положительное против часовой стрелки (CCW), 1 — по часовой стрелке (CW)
tbl-servo-max-speed = максимальная скорость (единица не подтверждена)
tbl-servo-profile-velocity = профильная (трапецеидальная) скорость для перемещений
tbl-servo-profile-acceleration = профильное (трапецеидальное) ускорение
tbl-servo-profile-deceleration = профильное (трапецеидальное) торможение
tbl-servo-quickstop-deceleration = торможение при быстром останове
tbl-servo-homing-method = способ возврата в исходное положение: 17/18 отрицательный/положительный концевой выключатель, 19-22 датчик исходного положения, 33/34 индексный импульс, 35/37 текущее положение (нумерация CiA 402)
tbl-servo-homing-speed-switch = скорость возврата при поиске датчика
tbl-servo-homing-speed-zero = скорость возврата при поиске нуля
tbl-servo-homing-offset-mode = режим смещения исходного положения Kinco: 0 — исходное положение равно 0, 1 — равно смещению (сохраняется; не подтверждено)
tbl-servo-homing-acceleration = ускорение возврата в исходное положение
tbl-servo-following-error-actual = фактическая ошибка рассогласования (в симуляторе: скорость x 2 мс)
tbl-servo-digital-inputs = дискретные входы: бит 0 отрицательный предел, бит 1 положительный предел, бит 2 исходное положение, бит 3 аппаратная блокировка
tbl-servo-digital-outputs = дискретные выходы (физические выходы DS402; сохраняется)
tbl-servo-target-velocity = заданная скорость для режимов скорости 3 и -3
tbl-servo-brake-resistor = сопротивление тормозного резистора
tbl-servo-brake-resistor-power = мощность тормозного резистора
tbl-servo-brake-resistor-time = постоянная времени тормозного резистора
tbl-servo-velocity-kp = пропорциональный коэффициент контура скорости (сохраняется)
tbl-servo-velocity-ki = интегральный коэффициент контура скорости (сохраняется)
tbl-servo-position-kp = пропорциональный коэффициент контура положения (сохраняется)
tbl-servo-drive-id = адрес привода на RS232 (по умолчанию 1; действует после перезапуска)
tbl-servo-din-polarity = полярность дискретных входов (сохраняется)
tbl-servo-din-simulate = имитируемые дискретные входы (сохраняется)
tbl-servo-din1-function = функция DIN1 (сохраняется; 0x10 положительный предел, 0x20 отрицательный предел по одному открытому C++-клиенту — не подтверждено)
tbl-servo-din2-function = функция DIN2 (сохраняется)
tbl-servo-din3-function = функция DIN3 (сохраняется)
tbl-servo-din4-function = функция DIN4 (сохраняется)
tbl-servo-din-real = дискретные входы по фактическому подключению (симулятор повторяет биты 0-2 объекта 60FD.00)
tbl-servo-dout1-function = функция DOUT1 (сохраняется)
tbl-servo-dout2-function = функция DOUT2 (сохраняется)
tbl-servo-dout-real = дискретные выходы в фактическом состоянии
tbl-servo-gear-factor = числитель электронного редуктора (импульсное задание, режим -4)
tbl-servo-gear-divider = знаменатель электронного редуктора (импульсное задание, режим -4; 0 не принимается)
tbl-servo-pulse-mode = режим импульсного входа: 0 CW/CCW, 1 импульс+направление, 2 A/B (x4, не подтверждено)
tbl-servo-pulse-filter = фильтр импульсного входа (сохраняется)
tbl-servo-pulse-frequency-control = управление частотой импульсов
tbl-servo-master-speed = частота импульсного входа (единица не подтверждена; в симуляторе: импульсов/мс)
tbl-servo-error-state = состояние ошибок Kinco (значения битов не подтверждены; симулятор устанавливает бит 0 при неисправности)
tbl-servo-baud-code = код скорости передачи данных RS232: 1080 = 9600, 540 = 19200, 270 = 38400 (по умолчанию), 90 = 115200; после перезапуска
tbl-servo-store-parameters = запишите 1, чтобы сохранить все параметры
tbl-servo-store-motor-data = запишите 1, чтобы сохранить данные двигателя
tbl-servo-display-select = выбор показаний 7-сегментного индикатора
tbl-servo-target-speed-rpm = заданная скорость в об/мин (пример RS232 из руководства FD5P записывает сюда 600 четырёхбайтной записью и читает двухбайтным ответом 4B; симулятор сохраняет значение)
tbl-servo-user-password = пароль пользователя
tbl-servo-encoder-resolution = разрешение энкодера (обратной связи) для формул DEC, инкрементов на оборот

## Servo engineering units (src/servo/units.rs; kinco-servo.md §4)

tbl-unit-bad-resolution = разрешение энкодера `{ $text }` — не целое число инкрементов на оборот в диапазоне 1…{ $max } (например, 10000 или 65536)
tbl-unit-unknown-speed = единица `{ $unit }` здесь неизвестна; для скорости пишите rpm или dec (единица привода): { $number }rpm
tbl-unit-unknown-accel = единица `{ $unit }` здесь неизвестна; для ускорения пишите rps/s или dec (единица привода): { $number }rps/s
tbl-unit-unknown-position = единица `{ $unit }` здесь неизвестна; для положения пишите rev или inc: { $number }rev
tbl-unit-not-a-number = `{ $number }` — не число (пишите, например, 300{ $suffix })
tbl-unit-takes = этот объект принимает { $raw } или { $eng }, а не { $suffix }
tbl-unit-takes-plain = этот объект принимает простые числа, а не { $suffix }
tbl-unit-not-whole = { $number }{ $suffix } — не целое число { $suffix }

## K2 model catalogue (src/k2/catalog.rs; K2 manual §1.2, §2.1.2, §2.2.6, §3.4)

tbl-model-unknown = неизвестная модель K2 `{ $name }`
tbl-model-unknown-hint = модели каталога: { $models }
tbl-model-k204et-1-what = максимальная частота HSC2/HSC3
tbl-model-k204et-1-chosen = 200 кГц для одной фазы и фазы AB (§2.2.6)
tbl-model-k204et-1-other = в §2.1.2 указано 20 кГц для одной фазы / 10 кГц для фазы AB в столбце CPU204 (столбец, по-видимому, сдвинут: он совпадает со строкой CPU209EA из §2.2.6)
tbl-model-k204et-2-what = максимальная частота Q0.4
tbl-model-k204et-2-chosen = 200 кГц (§2.2.6, §3.4)
tbl-model-k204et-2-other = в §2.1.2 указано 10 кГц в столбце CPU204
tbl-model-k209ea-1-what = максимальная частота Q0.4
tbl-model-k209ea-1-chosen = 10 кГц (§2.2.6, §3.4)
tbl-model-k209ea-1-other = в §2.1.2 в столбце CPU209EA указаны Q0.0, Q0.1, Q0.4 на 200 кГц и четвёртый выход Q0.5 (по-видимому, сдвинутая запись CPU209M)
tbl-model-k209ea-2-what = количество высокоскоростных счетчиков
tbl-model-k209ea-2-chosen = 4 (§2.2.6 приводит частоты HSC2/HSC3 для K209EA)
tbl-model-k209ea-2-other = в §2.1.2 в столбце CPU209EA напечатано 2 (по-видимому, сдвинутая запись CPU209M)
tbl-model-k205ea-1-what = частоты HSC и импульсных выходов
tbl-model-k205ea-1-chosen = 200 кГц на всех каналах (§2.1.2 — единственная таблица, где есть CPU205EA)
tbl-model-k205ea-1-other = в §2.2.6 и §3.4 нет CPU205EA

## Servo drive state machine (src/servo/ds402.rs; CiA 402 as the Kinco manual follows it). The CiA 402
## state and command names (operation enabled, switch on …) stay as they are: JSON reports carry them.

tbl-ds402-does-not-fit = { $value } не помещается в { $name } ({ $lo }…{ $hi })
tbl-ds402-or = { $a } или { $b }
tbl-ds402-step-stuck = команда { $what } (controlword 16#{ $cw }) не привела к состоянию { $want }: statusword 16#{ $sw } = { $state }
tbl-ds402-step-stuck-unknown = команда { $what } (controlword 16#{ $cw }) не привела к состоянию { $want }: statusword 16#{ $sw } = неизвестное состояние
tbl-ds402-in-fault-hint = привод в состоянии неисправности: выполните servo fault-reset
tbl-ds402-check-status-hint = проверьте servo status
tbl-ds402-in-fault = привод в состоянии неисправности (statusword 16#{ $sw })
tbl-ds402-in-fault-enable-hint = выполните servo fault-reset, затем servo enable
tbl-ds402-mode-readback = после записи режима работы { $mode } читается { $got }
tbl-ds402-not-enabled = { $what ->
    [move] нельзя выполнить перемещение
    [jog] нельзя выполнить Бег (JOG)
    [home] нельзя выполнить возврат в исходное положение
    [halt] нельзя выполнить остановку (halt)
    [release-halt] нельзя снять остановку (halt)
   *[other] нельзя выполнить { $what }
}: привод в состоянии «{ $state }» (statusword 16#{ $sw })
tbl-ds402-not-enabled-unknown = { $what ->
    [move] нельзя выполнить перемещение
    [jog] нельзя выполнить Бег (JOG)
    [home] нельзя выполнить возврат в исходное положение
    [halt] нельзя выполнить остановку (halt)
    [release-halt] нельзя снять остановку (halt)
   *[other] нельзя выполнить { $what }
}: привод в неизвестном состоянии (statusword 16#{ $sw })
tbl-ds402-not-enabled-hint = сначала выполните servo enable
tbl-ds402-buffer-full = буфер заданий привода оставался заполненным { $seconds } с (statusword 16#{ $sw }, бит 12 установлен при сброшенном бите 4)
tbl-ds402-buffer-full-hint = дождитесь окончания текущих перемещений (servo wait target), затем повторите
tbl-ds402-no-ack = привод не подтвердил задание (statusword 16#{ $sw }, бит 12 сброшен)
tbl-ds402-fault-while-waiting = привод перешёл в состояние неисправности во время ожидания (statusword 16#{ $sw })
tbl-ds402-fault-while-waiting-hint = servo status показывает состояние; servo fault-reset сбрасывает неисправность
tbl-ds402-homing-error = возврат в исходное положение завершился ошибкой (statusword 16#{ $sw }, бит 13)
tbl-ds402-homing-error-hint = проверьте способ возврата (6098.00) и датчики; servo status показывает биты
tbl-ds402-target-timeout = цель не достигнута за { $seconds } с (statusword 16#{ $sw })
tbl-ds402-target-timeout-at = цель не достигнута за { $seconds } с (statusword 16#{ $sw }, position_actual { $position })
tbl-ds402-target-timeout-hint = увеличьте timeout= или посмотрите причину в servo status

## The sandbox of graded and confined runs (src/confine.rs): bench actions a lab grants by name, and refusals

tbl-bench-refused = `{ $what }` недоступна проверяемой работе: это действие меняет стенд лабораторной работы, а не управляет им ({ $why })
tbl-bench-refused-hint = работа управляет устройствами лабораторной так же, как её программа на настоящей установке; лабораторная, которой это нужно, разрешает действие в lab.toml: grants = ["{ $what }"]
tbl-bench-other = меняет стенд
tbl-confine-no-write = запись { $path } в изолированном запуске не разрешена
tbl-confine-no-write-hint = дайте запуску каталог для файлов: plcsh run --sandbox --write-dir DIR
tbl-confine-write-outside = запись { $path } вне каталога { $dir }
tbl-confine-write-outside-hint = изолированный запуск пишет только в свой --write-dir
tbl-confine-real-device = { $url } — настоящее устройство: изолированный запуск открывает только симуляторы
tbl-confine-real-device-hint = в изоляции используйте sim:MODEL, sim-servo:, sim-umpk:MODEL или sim-fx:MODEL
tbl-confine-read-outside = чтение { $path } вне каталогов изолированного запуска
tbl-confine-read-outside-hint = изолированный запуск читает файлы только в { $folders }
tbl-confine-named-snapshot = именованный снимок `{ $name }` хранится в каталоге данных пользователя, к которому изолированный запуск не обращается
tbl-confine-named-snapshot-hint = укажите путь к файлу в каталоге записи, например out/start.json
tbl-confine-no-folder = нет каталогов
tbl-bench-sim-clock = показывает или меняет режим часов симулятора
tbl-bench-sim-input = задаёт сигнал на входе симулятора
tbl-bench-sim-quad = вращает имитируемый энкодер
tbl-bench-sim-inputs = перечисляет имитируемые входные сигналы
tbl-bench-sim-retain = меняет диапазоны сохранения (поддерживаемые батареей)
tbl-bench-sim-program = загружает, выгружает или читает программу ПЛК
tbl-bench-sim-cpu = запускает или останавливает CPU ПЛК
tbl-bench-sim-stop = переводит CPU ПЛК в режим STOP
tbl-bench-sim-pause = приостанавливает CPU ПЛК
tbl-bench-sim-switch = переключает переключатель RUN/STOP ПЛК
tbl-bench-sim-scan = выполняет сканирования ПЛК вручную
tbl-bench-sim-break = ставит точки останова в программе ПЛК
tbl-bench-sim-stepi = выполняет программу ПЛК по шагам
tbl-bench-sim-stepn = выполняет программу ПЛК по шагам
tbl-bench-sim-wire = соединяет имитируемые устройства
tbl-bench-sim-wires = перечисляет соединения
tbl-bench-sim-unwire = удаляет соединения
tbl-bench-sim-snapshot = восстанавливает сохранённое состояние симулятора
tbl-bench-sim-snapshots = перечисляет сохранённые состояния
tbl-bench-sim-fault = вносит или снимает неисправности
tbl-bench-sim-faults = перечисляет внесённые неисправности
tbl-bench-servo-sim = управляет симулятором сервопривода
tbl-bench-umpk-sim = управляет симулятором УМПК
tbl-bench-connect = открывает устройство
tbl-bench-close = закрывает устройство
tbl-bench-rtc-sync = устанавливает часы ПЛК по часам компьютера
tbl-bench-paths = показывает каталоги пользователя

## FX instruction subset and its load errors (src/fx/program.rs; FX programming manual ch. 2, 4, 5)

tbl-fx-unknown = неизвестная инструкция FX { $m }
tbl-fx-foreign-hint = { $m } — не мнемоника FX: на FX пишите { $how } (docs/il.md, The FX family)
tbl-fx-unknown-near = возможно, имелось в виду { $near }? (docs/il.md перечисляет подмножество FX)
tbl-fx-unknown-hint = docs/il.md перечисляет инструкции FX, которые выполняет симулятор
tbl-fx-operand-count = { $m } принимает { $want ->
    [one] { $want } операнд
    [few] { $want } операнда
   *[many] { $want } операндов
}, найдено { $found }
tbl-fx-operand-range = { $m } принимает от { $lo } до { $hi } операндов, найдено { $found }
tbl-fx-needs-preset = OUT { $t } нужна уставка: OUT { $t } K10 (константа) или OUT { $t } D10 (регистр)
tbl-fx-bad-preset = { $k }: уставка — это константа K… или регистр данных D…
tbl-fx-hsc-not-simulated = { $t }: высокоскоростные счетчики (C235–C255) не моделируются
tbl-fx-hsc-not-simulated-hint = используйте C0–C199 (16 бит) или C200–C234 (32 бит, вверх/вниз)
tbl-fx-out-one-operand = OUT { $t } принимает один операнд (уставка бывает только у таймеров и счетчиков)
tbl-fx-rst-target = RST { $t }: сбрасывает Y, M, S, D, таймер T или счетчик C
tbl-fx-input-written = { $m } { $t }: входы X программа записывать не может
tbl-fx-input-written-hint = пишите в Y, M, S (как KnY0 …), D или значение таймера или счетчика
tbl-fx-coil-target = { $m } { $t }: здесь программа управляет битами Y, M и S
tbl-fx-coil-target-hint = входы X приходят с объекта; таймерами и счетчиками управляют OUT T0 K10 / OUT C0 K5
tbl-fx-system-driven = { $m } { $t }: { $operand } управляется самим ПЛК
tbl-fx-not-on-model = { $t } нет на { $model }
tbl-fx-no-blocks = в списках FX здесь нет меток и программных блоков
tbl-fx-no-blocks-hint = пишите по одной инструкции в строке: LD X0 / OUT Y0 … END
tbl-fx-element-by-out = { $text }: таймерами и счетчиками FX управляет OUT
tbl-fx-element-by-out-hint = OUT T0 K50 (таймер), OUT C0 K10 (счетчик), RST T0 / RST C0
tbl-fx-foreign-ton = таймер как катушку с уставкой: LD X0 / OUT T0 K20 (T0–T199 считают по 100 мс)
tbl-fx-foreign-tof = задержку выключения катушкой таймера и LDI: LDI X0 / OUT T0 K20 (T0–T199 считают по 100 мс)
tbl-fx-foreign-tonr = катушку таймера с сохранением: OUT T250 K20 (T250–T255 сохраняют значение; RST T250 сбрасывает его)
tbl-fx-foreign-tp = импульс от катушки таймера: OUT T0 K20 с её контактом (T0–T199 считают по 100 мс)
tbl-fx-foreign-ctu = счетчик как катушку с уставкой: LD X0 / OUT C0 K10 (RST C0 сбрасывает его)
tbl-fx-foreign-ctd = счёт вниз 32-битным счетчиком: OUT C200 K10 при включённом M8200
tbl-fx-foreign-code = { $code }
tbl-fx-ld = начать блок нормально открытым контактом
tbl-fx-ldi = начать блок нормально закрытым контактом
tbl-fx-ldp = начать блок: включён на одно сканирование по переднему фронту бита
tbl-fx-ldf = начать блок: включён на одно сканирование по заднему фронту бита
tbl-fx-and = последовательный нормально открытый контакт
tbl-fx-ani = последовательный нормально закрытый контакт
tbl-fx-andp = последовательный контакт по переднему фронту
tbl-fx-andf = последовательный контакт по заднему фронту
tbl-fx-or = параллельный нормально открытый контакт
tbl-fx-ori = параллельный нормально закрытый контакт
tbl-fx-orp = параллельный контакт по переднему фронту
tbl-fx-orf = параллельный контакт по заднему фронту
tbl-fx-anb = AND двух последних блоков
tbl-fx-orb = OR двух последних блоков
tbl-fx-mps = сохранить результат операции в стеке
tbl-fx-mrd = прочитать сохранённый результат
tbl-fx-mpp = извлечь сохранённый результат
tbl-fx-inv = инвертировать результат операции
tbl-fx-out = OUT Y/M/S: катушка := результат; OUT Tn K|D: катушка таймера с уставкой; OUT Cn K|D: катушка счетчика
tbl-fx-set = если результат включён: установить Y/M/S (остаётся включённым)
tbl-fx-rst = если результат включён: сбросить Y/M/S, обнулить D, сбросить таймер или счетчик (значение 0, контакт выключен)
tbl-fx-pls = Y/M включён на одно сканирование после переднего фронта результата
tbl-fx-plf = Y/M включён на одно сканирование после заднего фронта результата
tbl-fx-mov = MOV S D: D := S (16 бит)
tbl-fx-movp = MOV по переднему фронту результата
tbl-fx-dmov = 32-битный MOV (D0 = младшее слово D0, старшее D1)
tbl-fx-dmovp = 32-битный MOV по переднему фронту
tbl-fx-add = ADD S1 S2 D: D := S1 + S2 (16 бит, с переполнением по кругу)
tbl-fx-addp = ADD по переднему фронту
tbl-fx-dadd = 32-битный ADD
tbl-fx-sub = SUB S1 S2 D: D := S1 − S2 (16 бит, с переполнением по кругу)
tbl-fx-subp = SUB по переднему фронту
tbl-fx-dsub = 32-битный SUB
tbl-fx-inc = D := D + 1 в каждом сканировании, пока результат включён
tbl-fx-incp = D := D + 1 по переднему фронту
tbl-fx-dec = D := D − 1 в каждом сканировании, пока результат включён
tbl-fx-decp = D := D − 1 по переднему фронту
tbl-fx-ld-eq = начать блок: S1 = S2 (16 бит)
tbl-fx-ld-gt = начать блок: S1 > S2
tbl-fx-ld-lt = начать блок: S1 < S2
tbl-fx-ld-ne = начать блок: S1 ≠ S2
tbl-fx-ld-le = начать блок: S1 ≤ S2
tbl-fx-ld-ge = начать блок: S1 ≥ S2
tbl-fx-and-eq = последовательный контакт: S1 = S2
tbl-fx-and-gt = последовательный контакт: S1 > S2
tbl-fx-and-lt = последовательный контакт: S1 < S2
tbl-fx-and-ne = последовательный контакт: S1 ≠ S2
tbl-fx-and-le = последовательный контакт: S1 ≤ S2
tbl-fx-and-ge = последовательный контакт: S1 ≥ S2
tbl-fx-or-eq = параллельный контакт: S1 = S2
tbl-fx-or-gt = параллельный контакт: S1 > S2
tbl-fx-or-lt = параллельный контакт: S1 < S2
tbl-fx-or-ne = параллельный контакт: S1 ≠ S2
tbl-fx-or-le = параллельный контакт: S1 ≤ S2
tbl-fx-or-ge = параллельный контакт: S1 ≥ S2
tbl-fx-ldd-eq = 32 бита: начать блок: S1 = S2
tbl-fx-ldd-gt = 32 бита: начать блок: S1 > S2
tbl-fx-ldd-lt = 32 бита: начать блок: S1 < S2
tbl-fx-andd-eq = 32-битный последовательный контакт: S1 = S2
tbl-fx-ord-eq = 32-битный параллельный контакт: S1 = S2
tbl-fx-nop = ничего
tbl-fx-end = конец программы: то, что следует дальше, не сканируется

## The K2's Modbus map (src/k2/modbus_map.rs; K2 manual §3.2.1). Modbus table names stay as they are.

tbl-modbus-word-order = `word_order={ $value }` — не порядок слов
tbl-modbus-word-order-hint = используйте word_order=high-first (порядок S7, по умолчанию) или word_order=low-first
tbl-modbus-not-in-map = { $operand } нет в карте Modbus K2: по Modbus K2 открывает только I, Q, M, V, AI и AQ (руководство §3.2.1); { $area } ({ $meaning }) недоступна
tbl-modbus-not-in-map-sm-hint = загрузите в ПЛК вспомогательную программу plcsh (lib/k2_agent.il, docs/agent.md) и подключайтесь с …&agent=VB3400; у симулятора (sim:MODEL) область SM доступна напрямую
tbl-modbus-not-in-map-tc-hint = копируйте таймеры и счетчики в V в программе ПЛК и читайте слова V; у симулятора (sim:MODEL) T и C доступны напрямую
tbl-modbus-past-end = { $operand } за концом области { $area } на { $model }
tbl-modbus-read-only = { $operand } по Modbus только для чтения ({ $meaning } — это { $table }, которые Modbus записать не может; руководство §3.2.1)
tbl-modbus-read-only-hint = входы определяются подключением на объекте; записывайте выход (Q, AQ) или память (M, V)

## FX timers and counters by class (src/fx/elements.rs; FX PM "Timers", "Counters")

tbl-element-timer = T{ $n }: таймер { $base } (T{ $first }–T{ $last }); контакт T{ $n } = TS{ $n }, катушка TC{ $n }, текущее значение TN{ $n }; в программе `OUT T{ $n } K50`
tbl-element-timer-retentive = T{ $n }: таймер { $base } с сохранением (RST сбрасывает его) (T{ $first }–T{ $last }); контакт T{ $n } = TS{ $n }, катушка TC{ $n }, текущее значение TN{ $n }; в программе `OUT T{ $n } K50`
tbl-element-counter = C{ $n }: 16-битный счетчик вверх (C0–C199); контакт C{ $n } = CS{ $n }, катушка CC{ $n }, текущее значение CN{ $n }
tbl-element-counter32 = C{ $n }: 32-битный счетчик вверх/вниз (C200–C234), считает вниз, пока включён M{ $relay }; контакт C{ $n } = CS{ $n }, текущее значение CN{ $n }
tbl-element-hsc = C{ $n }: высокоскоростной счетчик (C235–C255; не моделируется)

## The core IL instruction set (src/engine/isa.rs; K2 manual §3.4.3.1, K80S CPU chapter, IEC 61131-3, S7-200 convention)

tbl-il-ld = CR := бит (прежний CR сохраняется в стеке)
tbl-il-ldn = CR := NOT бит
tbl-il-and = CR := CR AND бит
tbl-il-a = CR := CR AND бит
tbl-il-andn = CR := CR AND NOT бит
tbl-il-an = CR := CR AND NOT бит
tbl-il-or = CR := CR OR бит
tbl-il-o = CR := CR OR бит
tbl-il-orn = CR := CR OR NOT бит
tbl-il-on = CR := CR OR NOT бит
tbl-il-xor = CR := CR XOR бит
tbl-il-xorn = CR := CR XOR NOT бит
tbl-il-and-paren = открыть: CR := CR AND ( … )
tbl-il-andn-paren = открыть: CR := CR AND NOT ( … )
tbl-il-or-paren = открыть: CR := CR OR ( … )
tbl-il-orn-paren = открыть: CR := CR OR NOT ( … )
tbl-il-xor-paren = открыть: CR := CR XOR ( … )
tbl-il-xorn-paren = открыть: CR := CR XOR NOT ( … )
tbl-il-close = закрыть самую внутреннюю скобку
tbl-il-not = CR := NOT CR
tbl-il-st = бит := CR
tbl-il-assign = бит := CR
tbl-il-stn = бит := NOT CR
tbl-il-s = если CR: установить бит (N бит — `S bit, N`; T/C включается)
tbl-il-r = если CR: сбросить бит (N бит); у таймера или счетчика обнуляются значение и бит
tbl-il-ald = AND двух верхних уровней логического стека
tbl-il-old = OR двух верхних уровней логического стека
tbl-il-lps = сохранить копию CR в стеке
tbl-il-lrd = CR := второй уровень стека
tbl-il-lpp = извлечь вершину стека в CR
tbl-il-r-trig = CR := CR вырос с прошлого выполнения этой инструкции
tbl-il-eu = передний фронт (имя R_TRIG в S7-200)
tbl-il-f-trig = CR := CR упал с прошлого выполнения этой инструкции
tbl-il-ed = задний фронт (имя F_TRIG в S7-200)
tbl-il-move = если CR: OUT := IN (тип OUT)
tbl-il-movb = пересылка байта
tbl-il-movw = пересылка слова
tbl-il-movd = пересылка двойного слова
tbl-il-movr = пересылка REAL
tbl-il-blkmove = если CR: копировать N элементов IN… → OUT…
tbl-il-bmb = блочная пересылка N байт
tbl-il-bmw = блочная пересылка N слов
tbl-il-bmd = блочная пересылка N двойных слов
tbl-il-fill = если CR: N слов начиная с OUT := IN
tbl-il-add = OUT := OUT + IN или OUT := IN1 + IN2
tbl-il-sub = OUT := OUT − IN или IN1 − IN2
tbl-il-mul = OUT := OUT × IN или IN1 × IN2
tbl-il-div = OUT := OUT ÷ IN или IN1 ÷ IN2 (÷0: ENO = 0)
tbl-il-mod = остаток от деления
tbl-il-add-i = сложение INT
tbl-il-sub-i = вычитание INT
tbl-il-mul-i = умножение INT
tbl-il-div-i = деление INT
tbl-il-add-d = сложение DINT
tbl-il-sub-d = вычитание DINT
tbl-il-mul-d = умножение DINT
tbl-il-div-d = деление DINT
tbl-il-add-r = сложение REAL
tbl-il-sub-r = вычитание REAL
tbl-il-mul-r = умножение REAL
tbl-il-div-r = деление REAL
tbl-il-inc = если CR: OUT := OUT + 1
tbl-il-dec = если CR: OUT := OUT − 1
tbl-il-shl = OUT := OUT, сдвинутый влево на N бит
tbl-il-shr = OUT := OUT, сдвинутый вправо на N бит (логический сдвиг)
tbl-il-rol = OUT := OUT, циклически сдвинутый влево на N бит
tbl-il-ror = OUT := OUT, циклически сдвинутый вправо на N бит
tbl-il-wand = OUT := OUT AND IN (побитно)
tbl-il-andw = побитовое AND
tbl-il-wor = OUT := OUT OR IN (побитно)
tbl-il-orw = побитовое OR
tbl-il-wxor = OUT := OUT XOR IN (побитно)
tbl-il-xorw = побитовое XOR
tbl-il-inv = OUT := NOT OUT (побитно)
tbl-il-sqrt = если CR: OUT := √IN (REAL); IN < 0 или NaN: ENO = 0, SM1.1, OUT не меняется; +inf: OUT = +inf, ENO = 0
tbl-il-abs = если CR: OUT := |IN| (тип OUT); −32768 / −2³¹ остаются собой с SM1.1 и ENO = 0; REAL NaN/inf: ENO = 0
tbl-il-swap = если CR: поменять местами старший и младший байты слова
tbl-il-for = FOR INDX, INIT, FINAL: если CR, выполнить инструкции до NEXT с INDX = INIT … FINAL (INT или DINT; INIT > FINAL: ни разу; вложенность ≤ 8)
tbl-il-next = конец цикла FOR: INDX + 1, возврат, пока INDX ≤ FINAL (FINAL читается заново; на максимуме типа цикл заканчивается)
tbl-il-i-di = INT → DINT
tbl-il-int-to-dint = INT → DINT
tbl-il-di-i = DINT → INT (вне диапазона: ENO = 0)
tbl-il-dint-to-int = DINT → INT
tbl-il-b-i = BYTE → INT
tbl-il-i-b = INT → BYTE (вне диапазона: ENO = 0)
tbl-il-di-r = DINT → REAL
tbl-il-round = REAL → DINT с округлением
tbl-il-trunc = REAL → DINT с отбрасыванием дробной части
tbl-il-i-bcd = INT 0…9999 → BCD (иначе ENO = 0)
tbl-il-bcd-i = BCD → INT (неверная цифра: ENO = 0)
tbl-il-jmp = переход на LABEL
tbl-il-jmpc = переход на LABEL, если CR
tbl-il-jmpcn = переход на LABEL, если NOT CR
tbl-il-cal = вызов подпрограммы NAME (если CR, по соглашению EN K2)
tbl-il-calc = вызов подпрограммы NAME, если CR
tbl-il-calcn = вызов подпрограммы NAME, если NOT CR
tbl-il-ret = возврат из этого POU
tbl-il-retc = возврат, если CR
tbl-il-retcn = возврат, если NOT CR
tbl-il-cret = условный возврат (имя в S7-200)
tbl-il-ton = таймер с задержкой включения Tn, PT (IN = CR; CR := Q)
tbl-il-tof = таймер с задержкой выключения Tn, PT
tbl-il-toff = таймер с задержкой выключения (имя в MASTER-K)
tbl-il-tp = импульсный таймер Tn, PT
tbl-il-tmr = накопительный таймер Tn, PT [, бит сброса]
tbl-il-tonr = накопительный таймер (имя в S7-200)
tbl-il-tmon = одновибратор Tn, PT
tbl-il-trtg = одновибратор с перезапуском Tn, PT
tbl-il-ctu = счетчик вверх Cn, PV [, бит сброса] (CU = CR)
tbl-il-ctd = счетчик вниз Cn, PV [, бит загрузки] (CD = CR)
tbl-il-ctud = счетчик вверх/вниз Cn, PV, бит CD [, бит сброса]
tbl-il-ctr = кольцевой счетчик Cn, PV [, бит сброса]
tbl-il-atch = связать программу обработки прерываний INT_NAME с событием EVENT
tbl-il-dtch = отвязать событие EVENT
tbl-il-eni = разрешить прерывания
tbl-il-disi = запретить прерывания (события ждут)
tbl-il-wdt = перезапустить счёт сторожевого таймера
tbl-il-wdr = перезапустить счёт сторожевого таймера (имя в S7-200)
tbl-il-nop = ничего
tbl-il-compare = сравнить IN1 с IN2 и загрузить результат в CR / объединить по AND / по OR
