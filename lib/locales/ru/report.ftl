# plcsh messages (ru): report. Same ids and arguments in en, ru and zh-CN (tests/messages.rs).

## Commissioning reports (src/report): headings and labels of the HTML report.
report-site = Объект
report-operator = Наладчик
report-date = Дата
report-time = Время
report-clock-stepped = моделируемое (пошаговое) время, от { $start } до { $end }
report-clock-real = время машины, от { $start } до { $end }
report-version = Создано
report-result-passed = ПРИНЯТО
report-result-failed = НЕ ПРИНЯТО
report-summary = выполнено шагов: { $ok } из { $total }, с ошибкой: { $failed }, пропущено: { $skipped }
report-devices = Устройства
report-no-devices = Ни одно устройство не было открыто.
report-device-family = Семейство
report-device-model = Модель
report-device-link = Адрес
report-device-kind = Вид
report-device-simulated = симулятор
report-device-real = реальное устройство
report-checklist = Перечень проверок
report-no-steps = Перечень проверок не выполнялся.
report-step = Шаг
report-result = Результат
report-duration = Длительность
report-note = Примечание
report-step-ok = выполнен
report-step-failed = ОШИБКА
report-step-failed-optional = ошибка (необязательный шаг)
report-step-skipped = пропущен
report-expected = Ожидалось
report-measured = Измерено
report-values = Измеренные значения
report-results = { $count ->
    [one] записан { $count } результат команды (в JSON-копии)
    [few] записано { $count } результата команд (в JSON-копии)
   *[many] записано { $count } результатов команд (в JSON-копии)
}
report-params = Наборы параметров
report-no-params = Наборы параметров не сохранялись, не загружались и не сравнивались.
report-params-saved = { $device }: сохранён в { $file }
report-params-loaded = { $device }: загружен из { $file }
report-params-compared = { $device }: сравнение
report-params-reference = Эталон: { $file }
report-params-same = Все параметры совпадают с эталоном.
report-parameter = Параметр
report-object = Объект
report-reference = Эталон
report-drive = Привод
report-curves = Графики
report-no-curves = Графики не записывались.
report-trace-caption = Выборок: { $samples } за { $span }.
report-trace-decimated = Построено и сохранено по минимуму и максимуму в каждом из { $columns } столбцов.
report-trace-step = Записано на шаге { $step }.
report-curve-figures = { $name }: мин. { $min }, макс. { $max }, последнее { $last }
report-writes = Запись в устройства
report-writes-none = plcsh ничего не записывал в устройства во время работы.
report-writes-not-kept = Ещё записей: { $count } (только подсчитаны).
report-device = Устройство
report-operand = Операнд или объект
report-old = Было
report-new = Стало
report-refused = отказ: { $reason }
report-notes = Заметки
report-no-notes = Заметок нет.
report-footer = Создано plcsh { $version }. На графиках не более двух точек на столбец пикселей (столбцов: { $columns }); в журнале записи хранятся первые { $writes } записей.
report-cannot-write = не удаётся записать отчёт { $file }: { $reason }
report-bad-record = не удаётся прочитать запись ввода в эксплуатацию: { $reason }
