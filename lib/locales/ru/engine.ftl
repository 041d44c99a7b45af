# plcsh messages (ru): engine — движок сканирования IL и его компилятор. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## Загрузка IL: чтение и компиляция (docs/il.md)

engine-comment-unclosed = комментарий `(*` нигде не закрыт `*)`
engine-line-too-long = строка длиннее { $max } символов
engine-empty-operand = пустой операнд в `{ $text }`
engine-no-program = в файле нет PROGRAM: основная программа выполняется в каждом цикле сканирования
engine-no-program-hint = начните основную программу с `PROGRAM MAIN` (или поставьте её перед первой SUBROUTINE)
engine-pou-twice = { $name } определён дважды
engine-label-twice = метка { $name } определена в { $pou } дважды
engine-for-too-deep = вложенность циклов FOR глубже { $max }
engine-next-without-for = NEXT без FOR
engine-next-without-for-hint = цикл записывается как FOR INDX, INIT, FINAL … NEXT в одном POU
engine-for-without-next = FOR без NEXT в { $pou }
engine-no-label = в { $pou } нет метки { $name }
engine-did-you-mean = может быть, { $name }?
engine-no-routine = в { $file } нет подпрограммы или программы обработки прерываний { $name }
engine-no-routine-hint = определите её: `SUBROUTINE NAME` (или `INTERRUPT NAME`) … `END_SUBROUTINE`
engine-needs-constant = { $mnemonic }: { $operand } должен быть константой
engine-unknown-instruction = неизвестная инструкция { $mnemonic }
engine-unknown-instruction-near = может быть, { $name }? (список инструкций — в docs/il.md)
engine-unknown-instruction-hint = инструкции, которые выполняет этот симулятор, перечислены в docs/il.md
engine-pointer-not-dword = { $operand }: указатель — это двойное слово, а { $target } — нет
engine-pointer-not-dword-hint = храните указатели в двойных словах, например *%VD{ $index }
engine-not-pointable = { $operand }: на { $target } нельзя указать
engine-not-pointable-hint = указывать можно на байты V, M, I, Q или SM
engine-operand-type = { $name } имеет тип { $have }, а эта операция работает с { $want }
engine-pointer-needs-dword = { $operand }: указателю нужно двойное слово
engine-output-not-location = в { $operand } нельзя записать: выход должен быть адресом в памяти
engine-not-a-bit = { $name } имеет тип { $have }, а не бит
engine-not-a-bit-hint = битовые операнды выглядят так: %M0.0, %I0.1, %SM0.0 (или T5/C5 — бит таймера или счетчика)
engine-bit-needed = { $operand }: здесь нужен адрес бита
engine-count-range = { $operand }: ожидается количество от 1 до 255
engine-convert-first = сначала преобразуйте: { $how }
engine-same-size = используйте операнды одного размера (B, W, D)
engine-numbers-not-bits = { $mnemonic } работает с числами, а не с битами
engine-int-dint-real = { $mnemonic } работает со значениями INT, DINT или REAL
engine-no-event = ATCH: нет события прерывания { $event } (события: { $events })
engine-block-n = { $mnemonic }: N должно быть от 1 до 255, а указано { $n }
engine-timer-preset-range = { $time } — это { $units } { $units ->
    [one] единица
    [few] единицы
   *[many] единиц
} этого таймера { $base } мс; заданное значение должно быть от 0 до 32767 (не более { $longest } с)
engine-timer-rounded = { $time } не делится на единицы этого таймера ({ $base } мс): округлено вверх до { $got } мс ({ $units } { $units ->
    [one] единица
    [few] единицы
   *[many] единиц
}), задержка не короче заданной

## Выполнение: неисправности (K2 §2.2.1, серьёзные и нормальные ошибки)

engine-fault = неисправность { $code } ({ $name }): { $message }
engine-fault-at = неисправность { $code } ({ $name }): { $message }, строка { $line } `{ $instruction }`
engine-fault-watchdog = сторожевой таймер
engine-fault-bad-address = неверный косвенный адрес
engine-fault-call-depth = глубина вызовов
engine-fault-instruction = инструкция
engine-fault-div-zero = деление на ноль
engine-ran-off = выполнение вышло за конец программы
engine-parens-too-deep = вложенность скобок глубже { $max }
engine-division-by-zero = деление на ноль
engine-calls-too-deep = вложенность подпрограмм глубже { $max }
engine-watchdog = цикл сканирования превысил предел сторожевого таймера { $ms } мс (бесконечный цикл?)
engine-block-length = длина блока { $n } вне диапазона 1…255
engine-no-destination = нет адреса назначения
engine-bad-address = неверный косвенный адрес
engine-bad-address-at = неверный косвенный адрес { $pointer }

## Собственные инструкции семейств (таблицы docs/il.md: руководство K2 §3.3, §3.4; FX PM; УМПК §3.5)

engine-doc-k2-pls = PLS q: загрузить настройки SM канала и запустить PTO/PWM (по переднему фронту EN); CR не меняется — при отказе устанавливается только бит состояния SM66.4 …
engine-doc-k2-hdef = HDEF hsc, mode: назначить режим счетчика
engine-doc-k2-hsc = HSC n: применить байт управления и запустить или остановить счетчик
engine-doc-k2-pstop = PSTOP AXIS[, EXEC, DONE, ERRID]: аварийный останов по переднему фронту EXEC (или EN, если EXEC нет); фиксирует SM201.7
engine-doc-k2-prel = PREL AXIS, EXEC, MINF, MAXF, TIME, DIST, DONE, ERR, ERRID: относительное перемещение с разгоном MINF→MAXF за TIME мс, по переднему фронту EXEC
engine-doc-k2-pabs = PABS AXIS, EXEC, MINF, MAXF, TIME, POS, DONE, ERR, ERRID: абсолютное перемещение в POS (SMD212 …)
engine-doc-k2-phome = PHOME AXIS, EXEC, HOME, NHOME, MODE, DIRC, MINF, MAXF, TIME, DONE, ERR, ERRID: движение в направлении DIRC до HOME (MODE 0: после NHOME медленно на MINF)
engine-doc-k2-pjog = PJOG AXIS, EXEC, MAXF, DIRC, DONE, ERR, ERRID: движение на MAXF (читается в каждом цикле сканирования), пока EXEC включён
engine-doc-k2-pflo-f = PFLO_F AXIS, EXEC, F, NUM, DENOM, COUNT, DONE, ERR, ERRID: следовать частоте F × NUM / DENOM Гц в течение COUNT импульсов (≥ 30 Гц)
engine-doc-k2-read-rtc = READ_RTC buf: 8 байт BCD: гг мм дд чч мм сс 00 день недели
engine-doc-k2-set-rtc = SET_RTC buf: установить часы из 8 байт BCD (неверные данные: ENO = 0)
engine-doc-k2-stop = если CR: CPU переходит в STOP в конце этого цикла сканирования (выходы — в свои значения для STOP; `sim cpu run` запускает снова)
engine-doc-fx-fxtim = OUT Tn K|D: катушка таймера FX (вход = CR, CR не меняется)
engine-doc-fx-fxcnt = OUT Cn K|D: катушка 16-битного счетчика FX
engine-doc-fx-fxcnt32 = OUT Cn K|D: катушка 32-битного реверсивного счетчика FX
engine-doc-fx-fxrst = RST D/T/C: сбросить регистр, таймер или счетчик
engine-doc-umpk-timer = TIMER Tn, GROUP, STEPS: таймер с задержкой включения, вход = CR, задержка STEPS (1–255) × GROUP (0: 10 мс, 1: 0,1 с, 2: 1 с); CR := Tn
engine-doc-umpk-divide = DIVIDE Cn, RATIO[, RESET]: делитель импульсов CR на N (RATIO 1–255); выходной импульс длится столько же, сколько входной; RESET сбрасывает его; CR := Cn
engine-doc-umpk-error = ERROR CODE: по переднему фронту CR записывает код ошибки пользователя CODE (1–127) в историю ошибок (?07F9); программа продолжает работу

## Коды завершения (docs/reference/exit-status.md строится из них, на английском)

exit-ok-name = ok
exit-ok-when = все команды выполнены; скрипт завершился; ответило каждое устройство группы; `sim serve` остановлен сигналом SIGTERM, SIGHUP или Ctrl-C; `publish` остановлен Ctrl-C, SIGTERM или SIGHUP после доставки всех показаний
exit-failed-name = ошибка
exit-failed-when = команда, скрипт или проверка завершились ошибкой (какой — сказано в сообщении `error[KIND]`); на одном из устройств группы произошла ошибка; критерий лабораторной работы не выполнен; повреждённая запись показана частично
exit-usage-name = неверный вызов
exit-usage-when = неверная командная строка: неизвестный флаг или подкоманда, нет значения или оно неверно, файл, указанный в --config, не существует, запись не читается
exit-broker-refused-name = брокер отказал
exit-broker-refused-when = `publish`: брокер MQTT отверг учётные данные (имя пользователя, пароль или его ACL)
exit-broker-unreachable-name = брокер недоступен
exit-broker-unreachable-when = `publish`: TLS-сертификат брокера не прошёл проверку, или ни один брокер не ответил в течение 10 с после запуска
exit-hangup-name = SIGHUP
exit-hangup-when = терминал пропал (оборвался сеанс SSH; Windows: закрыто окно консоли); выполняемая команда остановлена, обработчики прерывания выполнены
exit-interrupted-name = Ctrl-C
exit-interrupted-when = Ctrl-C остановил разовую команду, скрипт или работу с группой устройств; обработчики прерывания выполнены (в интерактивной оболочке Ctrl-C вместо этого возвращает к приглашению)
exit-terminated-name = SIGTERM
exit-terminated-when = SIGTERM (`timeout`, `systemctl stop`, CI; Windows: Ctrl-Break) остановил работу; обработчики прерывания выполнены
