# plcsh messages (ru): agent — программа-помощник в ПЛК и её проверки. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## PLS refused on a value kept from an earlier PLS (update bit clear; K2 §3.4.2.2): the same
## words in process and through the helper (k2::sim::pto::explain).
agent-pls-kept-cycle = сохранённое ранее время цикла неверное: бит обновления SM{ $control }.0 сброшен, поэтому PLS взяла значение, загруженное предыдущей PLS (0 после включения питания), а не SMW{ $cycle } (время цикла и количество импульсов должны быть больше 1, §3.4.2.2; частота — в пределах выхода, §3.4)
agent-pls-kept-cycle-hint = задайте SMW{ $cycle } и его бит обновления SM{ $control }.0, затем снова PLS
agent-pls-kept-count = сохранённое ранее количество импульсов неверное: бит обновления SM{ $control }.2 сброшен, поэтому PLS взяла значение, загруженное предыдущей PLS (0 после включения питания), а не SMD{ $count } (время цикла и количество импульсов должны быть больше 1, §3.4.2.2)
agent-pls-kept-count-hint = задайте SMD{ $count } и его бит обновления SM{ $control }.2, затем снова PLS
agent-pls-kept-both = сохранённое ранее время цикла или количество импульсов неверное: биты обновления SM{ $control }.0 и SM{ $control }.2 сброшены, поэтому PLS взяла значения, загруженные предыдущей PLS (0 после включения питания), а не SMW{ $cycle } и SMD{ $count } (время цикла и количество импульсов должны быть больше 1, §3.4.2.2)
agent-pls-kept-both-hint = задайте SMW{ $cycle }, SMD{ $count } и их биты обновления SM{ $control }.0 и SM{ $control }.2 (например, SMB{ $control }=16#85), затем снова PLS

# An instruction the helper ran whose status register reports something the PLC does not
# refuse for (HSC's multi-PV table fault, §3.3.2): what ran, then the note.
agent-done-with-note = { $what }: выполнено программой-помощником; { $note }

# The mailbox base (`agent install base=`, `sm … base=`): below the E2PROM area (§2.2.8).
agent-base-not-vb = `{ $text }` — не адрес байта V (например, VB{ $base })
agent-base-range = почтовому ящику программы-помощника нужен чётный адрес и { $total } свободных байт ниже области резервного копирования данных (E2PROM) VB{ $eeprom } (задано VB{ $n })

# The helper's result codes, as a refusal reads them.
agent-result-done = выполнено
agent-result-unknown-command = программа-помощник не знает этой команды (обновите lib/k2_agent.il)
agent-result-bad-range = диапазон SM выходит за регистры, названные в руководстве, или длиннее 64 байт
agent-result-read-only = байты SM только для чтения
agent-result-bad-channel = такого канала в этом ПЛК нет
agent-result-bad-mode = у счетчика нет такого режима
agent-result-instruction-failed = инструкция ПЛК сообщила об ошибке (её ENO)
agent-result-bad-clock = неверная дата или время
agent-result-status-bit = бит состояния инструкции сообщает об отказе
agent-result-other = неизвестный код результата { $code }

# The helper's causes of a status-bit refusal (§3.4.2.2, §3.4.3.1, §3.3.2).
agent-pls-invalid = ПЛК установил бит состояния SM{ $status }.4 после PLS { $n }: неверное время цикла или количество импульсов (время цикла и количество импульсов должны быть больше 1, §3.4.2.2); импульсы не выданы
agent-pls-invalid-hint = загрузите SMW{ $cycle } с установленным SM{ $control }.0 и SMD{ $count } с установленным SM{ $control }.2 (например, SMB{ $control }=16#85), затем снова PLS
agent-pstop-not-latched = бит аварийного останова SM{ $control }.7 не установился после PSTOP { $n } (§3.4.3.1 руководства: PSTOP его устанавливает)
agent-pstop-not-latched-hint = проверьте, что в ПЛК работает текущая программа-помощник и что этот канал позиционирования в нём есть
agent-hsc-pv-table = ПЛК установил бит состояния SM{ $status }.3 после HSC { $n }: ошибка в таблице нескольких PV (§3.3.2 руководства)
agent-hsc-pv-table-hint = проверьте таблицу PV по адресу SMW{ $table } (нечётный адрес V, количество 1..32, PV, отличающиеся больше чем на 1; §3.3.3)

# `plcsh agent check` (docs/agent.md, "agent check"): what each step proves, what it saw and
# what to do when it failed; then the verdict.
agent-check-proves-signature = программа-помощник работает с почтовым ящиком по этому адресу (plcsh читает там свою подпись)
agent-check-proves-protocol = программа-помощник говорит на той же версии протокола почтового ящика, что и этот plcsh
agent-check-proves-heartbeat = программа-помощник вызывается в каждом цикле сканирования, поэтому команды принимаются за один-два цикла; по частоте видно время сканирования
agent-check-proves-system-bits = копирование SM программой-помощником доходит до битов состояния системы: команда уходит, ответ приходит, и байты — собственные байты ПЛК
agent-check-proves-clock = READ_RTC работает через программу-помощник, и часы реального времени ПЛК идут
agent-check-proves-refusal = инструкция, которую ПЛК отвергает, сообщается как отказ (бит состояния 4), а не как выполненная, и отказ ничего не двигает
agent-check-not-run = не выполнен: предыдущий шаг не прошёл
agent-check-not-run-todo = исправьте первый непройденный шаг, затем снова запустите plcsh agent check
agent-check-install = загрузите программу-помощник в ПЛК (её выводит plcsh agent il --base VB{ $base }; docs/reference/first-connection.md) или укажите адрес, для которого она сделана (agent=VB…)
agent-check-link-probe = проверьте связь (plcsh probe URL покажет, что отвечает ПЛК)
agent-check-signature-seen = VW{ $base } = 16#{ $got } (программа-помощник пишет 16#{ $want })
agent-check-version-seen = версия { $got } (этот plcsh говорит на версии { $want })
agent-check-version-todo = загрузите текущую программу-помощник: plcsh agent il (затем снова запустите plcsh agent check)
agent-check-link = проверьте связь
agent-check-heartbeat-stopped = счетчик циклов оставался равным { $hb } в течение { $ms } мс
agent-check-heartbeat-todo = переведите ПЛК в RUN и проверьте, что основная программа вызывает программу-помощник в каждом цикле (LD %SM0.0 / CAL PLCSH_AGENT)
agent-check-heartbeat-seen = { $scans } { $scans ->
        [one] цикл
        [few] цикла
       *[many] циклов
    } за { $ms } мс: { $rate } циклов в секунду, время сканирования около { $scan } мс
agent-check-sm00-todo = SM0.0 читается как 0, хотя в работающем ПЛК всегда равен 1 (руководство, таблица SM): программа-помощник копирует другую память; проверьте, что программа-помощник сделана для этой модели (plcsh agent il), и приложите вывод plcsh agent check --json к вопросу
agent-check-sm01-todo = SM0.1 (первый цикл сканирования) читается как 1 спустя долгое время после первого цикла: копия SM программы-помощника не следует за байтами SM ПЛК; загрузите текущую программу-помощник (plcsh agent il)
agent-check-reply-length = в ответе { $n } { $n ->
        [one] байт
        [few] байта
       *[many] байт
    }, а не 1
agent-check-load-current-il = загрузите текущую программу-помощник (plcsh agent il)
agent-check-mailbox-todo = проверьте, что почтовым ящиком не пользуется другой клиент, затем запустите проверку снова
agent-check-rtc-short = ответ программы-помощника на READ_RTC короче 8 байт
agent-check-rtc-invalid = часы ПЛК показывают { $reading }
agent-check-rtc-invalid-hint = установите их: plcsh -d URL -c 'rtc set YYYY-MM-DDTHH:MM:SS' (возможно, разряжена батарея часов)
agent-check-clock-seen = { $first }, затем { $second } через { $dt } с ({ $moved } с по часам ПЛК)
agent-check-clock-todo = часы ПЛК не идут: проверьте батарею часов и установите часы (rtc set …)
agent-check-relay-model = у { $model } релейные выходы и нет импульсного канала (§2.2.6 руководства): проверять нечего
agent-check-again = запустите проверку снова
agent-check-all-enabled = у каждого импульсного канала установлен бит разрешения ({ $bytes }): программа их использует
agent-check-all-enabled-todo = проверка пробует PLS только на канале, который программа оставляет запрещённым; запускайте её, когда программа не использует импульсный канал (тестовая программа или отключённые выходы машины)
agent-check-restore-failed = { $name }: байты не удалось записать обратно: { $error }
agent-check-restore-todo = запишите их обратно вручную: SMB{ $control } = 16#{ $value }, SMD{ $count } = { $pulses }
agent-check-wrong-length = ответ неверной длины
agent-check-load-current = загрузите текущую программу-помощник
agent-check-reported-done = программа-помощник сообщила, что инструкция выполнена
agent-check-reported = программа-помощник сообщила: { $message }
agent-check-refusal-seen = { $name }: состояние SMB{ $status } 16#{ $before } → 16#{ $after } (бит 4 { $bit4 ->
        [set] установлен
       *[clear] сброшен
    }), положение SMD{ $cv } { $moved ->
        [changed] ИЗМЕНИЛОСЬ
       *[unchanged] не изменилось
    }; { $helper }; записаны обратно: { $written }
agent-check-no-bit4-todo = ПЛК не отметил неверное количество импульсов в байте состояния (§3.4.2.2 руководства, бит 4): возможно, программа-помощник обращается не к тем байтам SM этого ПЛК; приложите вывод plcsh agent check --json к вопросу
agent-check-cr-todo = программа-помощник считает успехом CR после PLS, а K2 оставляет его без изменений (§3.4.2, IL): отвергнутая PLS выглядела бы выполненной; загрузите текущую программу-помощник (plcsh agent il)
agent-check-moved-todo = канал сдвинулся: остановите машину и проверьте канал { $channel }, прежде чем пользоваться импульсными выходами
agent-check-title = программа-помощник по адресу { $base } в { $model }
agent-check-proves = доказывает: { $text }
agent-check-todo = что делать: { $text }
agent-check-passed = все шаги пройдены
agent-check-failed = проверка НЕ ПРОЙДЕНА

# The client of the helper's mailbox (docs/agent.md): what a request did, whether the helper
# is there and current, and why a request did not run.
agent-what-sm-write = запись SMB{ $start }…SMB{ $end }
agent-what-sm-read = чтение SMB{ $start }…SMB{ $end }
agent-no-helper = в VB{ $base }…VB{ $last } не отвечает программа-помощник plcsh (подпись 16#{ $got }, ожидалась 16#{ $want })
agent-no-helper-hint = для регистров SM и инструкций в ПЛК нужна программа-помощник: её выводит `plcsh agent il --base VB{ $base }` (также lib/k2_agent.il); как её установить, описано в docs/agent.md; или проверьте, что agent=VB… совпадает с программой
agent-helper-v2 = программа-помощник в ПЛК версии 2, она сообщает об отвергнутой PLS как о выполненной (читает CR, который PLS оставляет без изменений, §3.4.2 руководства)
agent-helper-v1 = программа-помощник в ПЛК версии 1, она выполняет повторную PLS или PSTOP на канале только в первый раз
agent-helper-old-hint = загрузите в ПЛК текущую программу-помощник (версии { $version }): её выводит `plcsh agent il --model MODEL` (lib/k2_agent.il)
agent-helper-version = программа-помощник в ПЛК говорит на версии { $got } протокола почтового ящика; этот plcsh — на версии { $want }
agent-helper-version-hint = загрузите текущую программу-помощник: `plcsh agent il` (lib/k2_agent.il)
agent-mailbox-busy = почтовый ящик занят: не удалось отправить { $what }
agent-mailbox-busy-hint = запрос другого клиента (номер { $pending }) ждёт программу-помощник уже { $ms } мс; ПЛК в режиме RUN? повторите попытку
agent-reply-short = ответ программы-помощника на { $what } короче запрошенного
agent-refused = программа-помощник отвергла { $what }: { $why } (результат { $result }, причина { $cause })
agent-no-ack = программа-помощник не подтвердила { $what } за { $ms } мс
agent-no-ack-stopped = счетчик циклов программы-помощника остановился: вероятно, ПЛК в режиме STOP или программа-помощник больше не вызывается в каждом цикле сканирования
agent-no-ack-busy = программа-помощник работает, но не приняла запрос; возможно, почтовым ящиком пользуется другой клиент
agent-mailbox-races = почтовый ящик занят: { $what } — другие клиенты опередили этот запрос { $races } { $races ->
        [one] раз
        [few] раза
       *[many] раз
    }
agent-mailbox-races-hint = другой plcsh (или программа) одновременно отправляет этому ПЛК команды программы-помощника; повторите попытку
agent-heartbeat-stopped = программа-помощник plcsh установлена, но её счетчик циклов не изменился за { $ms } мс
agent-heartbeat-stopped-hint = вероятно, ПЛК в режиме STOP или PLCSH_AGENT вызывается не в каждом цикле сканирования (LD %SM0.0 / CAL PLCSH_AGENT)

# The probe's Markdown report (`plcsh probe … --report FILE`): its title, lines and headings.
agent-probe-report-title = Отчёт plcsh probe
agent-probe-report-device = устройство: `{ $url }`
agent-probe-report-requests = отправлено запросов: { $requests } (только чтение: FC 01, 02, 03, 04)
agent-probe-report-areas = Области Modbus
agent-probe-report-models = Подходящие модели из каталога
agent-probe-report-no-models = нет
agent-probe-report-timing = Время ответа
agent-probe-report-timed = чтений { $what }: { $reads }, неудачных: { $failed }; p50 { $p50 }, p99 { $p99 }, max { $max }
agent-probe-report-verdicts = Заключения

# The helper's checks (k2::agent::protocol::checks): the reason of each row, in the helper
# program's comments and docs/agent.md (English) and in a refusal a person reads.
agent-row-commands = программа-помощник знает команды 1..9
agent-row-smb0 = SMB0 содержит биты состояния системы и доступен только для чтения
agent-row-length = за один раз 1..{ $max } байт
agent-row-start = начало — SMB0..SMB{ $last }, регистры, названные в руководстве
agent-row-end = последний байт — не дальше SMB{ $last } (SMD{ $dword } — последний регистр, названный в руководстве)
agent-row-block = SMB{ $first }..SMB{ $last } — один блок: разделите запрос на его границе
agent-row-gap = { $bytes }: руководство не называет здесь регистров { $model }
agent-row-pos-cv = SMD{ $at } только для чтения (§3.4.3.1)
agent-row-no-pto = у { $model } нет импульсных выходов
agent-row-no-hsc = у { $model } нет высокоскоростных счетчиков
agent-row-pto = у { $model } импульсные выходы 0..{ $last }
agent-row-hsc = у { $model } высокоскоростные счетчики 0..{ $last }
agent-result-because = { $result }: { $why }
