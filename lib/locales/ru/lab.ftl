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
