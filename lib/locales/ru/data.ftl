# plcsh messages (ru): data. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).

## Наборы данных (dataset, data save/diff/load)

data-usage = как вызывать: data save FILE OPERAND… | data diff FILE [FILE2] | data load FILE
data-cannot-read = не удаётся прочитать { $file }
data-bad-file = { $file } не является файлом набора данных: { $reason }
data-no-identity = { $file } не является файлом набора данных: в его таблице [device] не указаны семейство или модель
data-bad-operand = в { $file } указан `{ $operand }`, что не является именем операнда: пустое, с пробелом или длиннее 128 символов
data-bad-type = в { $file } операнду { $operand } задан тип `{ $dtype }`; типы: BOOL, BYTE, SINT, WORD, INT, DWORD, DINT и REAL
data-bad-value = { $file }: { $value } не является значением типа { $dtype } для { $operand }
data-duplicate = в { $file } операнд { $operand } указан дважды
data-other-device = { $file } содержит данные { $family } { $model }, а { $device } — это { $dfamily } { $dmodel }: набор данных загружается только в устройство того семейства и той модели, из которого он прочитан
data-families-differ = { $left } содержит данные семейства { $lfamily }, а { $right } — семейства { $rfamily }: сравниваются только наборы одного семейства
data-unknown-operand = в { $file } указан { $operand } типа { $dtype }, но у { $device } нет одного такого операнда этого типа: { $reason }
data-operand-elsewhere = { $operand } относится к другому устройству; набор данных содержит операнды одного устройства ({ $device })
data-no-area = `{ $area }` обозначает область ПЛК K2, а { $device } не K2: укажите его операнды
data-retained-unknown = диапазоны сохранения реального K2 задаются в его аппаратной конфигурации (KincoBuilder), которую нельзя прочитать по Modbus: укажите их, например data save FILE VB0..VB99 для { $device }
data-retained-none = у { $device } нет диапазонов сохранения: `sim retain VB0..VB99` задаёт диапазоны сохранения симулятора
data-saved = { $count ->
        [one] сохранён { $count } операнд
        [few] сохранено { $count } операнда
       *[many] сохранено { $count } операндов
    } { $device } в { $file }
data-same = различий нет
data-loaded = { $written ->
        [one] записан { $written } операнд
        [few] записано { $written } операнда
       *[many] записано { $written } операндов
    }, каждый прочитан обратно; без изменений: { $unchanged }
data-read-back = { $operand } после записи { $value } читается как { $back }; загрузка остановлена здесь после { $written ->
        [one] { $written } записи
       *[other] { $written } записей
    }
data-stopped = загрузка остановлена на { $operand } после { $written ->
        [one] { $written } записи
       *[other] { $written } записей
    }: { $reason }
data-not-a-drive = { $device } не является сервоприводом: servo params diff --with указывает другой открытый привод
