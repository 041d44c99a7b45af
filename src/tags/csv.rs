//! Tag tables as CSV: what KincoBuilder's global variable table exports and what a
//! spreadsheet saves — columns name, address, type, comment, separated by `,`, `;` (a
//! spreadsheet in a Russian or German locale) or a tab (copied from a grid).
//!
//! The separator is the one of tab, `;`, `,` that occurs most often outside quotes in the
//! first non-blank line (tab, then `;`, on a tie). Fields may be quoted the way RFC 4180
//! and every spreadsheet quote them: `"…"` with `""` for a quote, a separator or a line
//! break inside. The first row is a header when its cells are column words (below) — then
//! the columns may come in any order, and columns with other words (an initial value, a
//! retain flag) are left out; otherwise the columns are name, address, type, comment in that
//! order. The manuals do not describe KincoBuilder's export, so the header words are the ones
//! its English, Russian and Chinese interfaces and common spreadsheets use. Blank rows are
//! skipped, and so are rows whose first cell starts with `#` or `//` (a note in the table).
//!
//! One pass over the text; every field keeps its line and column for problems.

use super::name::address_text;
use super::{Problems, Tag, TagType};
use crate::msg;

/// Which column a header cell names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Column {
    Name,
    Address,
    Type,
    Comment,
}

/// Header words (compared in lower case, spaces and `_` removed), by column.
const HEADER_WORDS: &[(Column, &[&str])] = &[
    (
        Column::Name,
        &[
            "name",
            "symbol",
            "symbolname",
            "tag",
            "tagname",
            "variable",
            "variablename",
            "var",
            "identifier",
            "имя",
            "символ",
            "название",
            "переменная",
            "тег",
            "имятега",
            "имяпеременной",
            "名称",
            "变量名",
            "变量",
            "符号",
            "符号名",
            "标签",
            "名字",
        ],
    ),
    (Column::Address, &["address", "addr", "location", "адрес", "地址", "变量地址"]),
    (Column::Type, &["type", "datatype", "тип", "типданных", "数据类型", "类型"]),
    (
        Column::Comment,
        &[
            "comment",
            "comments",
            "description",
            "remark",
            "комментарий",
            "описание",
            "примечание",
            "注释",
            "说明",
            "描述",
            "备注",
        ],
    ),
];

fn header_column(cell: &str) -> Option<Column> {
    let key: String = cell.trim().to_lowercase().chars().filter(|c| !c.is_whitespace() && *c != '_').collect();
    HEADER_WORDS.iter().find(|(_, words)| words.contains(&key.as_str())).map(|(c, _)| *c)
}

/// One field as read, with where it starts (1-based line and column, in characters).
#[derive(Debug)]
struct Field {
    text: String,
    line: usize,
    col: usize,
}

/// The separator: the most frequent of tab, `;`, `,` outside quotes in the first non-blank line.
fn separator(text: &str) -> char {
    let first = text.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
    let mut counts = [0usize; 3];
    let mut quoted = false;
    for c in first.chars() {
        match c {
            '"' => quoted = !quoted,
            '\t' if !quoted => counts[0] += 1,
            ';' if !quoted => counts[1] += 1,
            ',' if !quoted => counts[2] += 1,
            _ => {}
        }
    }
    let best = (0..3).max_by_key(|&i| (counts[i], 3 - i)).unwrap_or(2);
    if counts[best] == 0 {
        return ',';
    }
    ['\t', ';', ','][best]
}

/// Splits the text into records of fields (RFC 4180 quoting). An unclosed quote is a problem
/// at the quote; what was read before it is kept.
fn records(text: &str, sep: char, problems: &mut Problems<'_>) -> Vec<Vec<Field>> {
    let mut out = Vec::new();
    let mut record: Vec<Field> = Vec::new();
    let mut field = Field { text: String::new(), line: 1, col: 1 };
    let (mut line, mut col) = (1usize, 1usize);
    let mut chars = text.chars().peekable();
    let mut at_start = true; // at the start of a field
    let mut quoted: Option<(usize, usize)> = None; // where the open quote is
    while let Some(c) = chars.next() {
        let (here_line, here_col) = (line, col);
        if c == '\n' {
            line += 1;
            col = 1;
        } else {
            col += 1;
        }
        if quoted.is_some() {
            if c == '"' {
                if chars.peek() == Some(&'"') {
                    chars.next();
                    col += 1;
                    field.text.push('"');
                } else {
                    quoted = None;
                }
            } else {
                field.text.push(c);
            }
            continue;
        }
        if at_start {
            field.line = here_line;
            field.col = here_col;
            at_start = false;
        }
        if c == sep {
            record.push(std::mem::replace(&mut field, Field { text: String::new(), line, col }));
            at_start = true;
        } else if c == '\n' {
            if field.text.ends_with('\r') {
                field.text.pop();
            }
            record.push(std::mem::replace(&mut field, Field { text: String::new(), line, col }));
            out.push(std::mem::take(&mut record));
            at_start = true;
        } else if c == '"' && field.text.trim().is_empty() {
            // A quote after leading spaces opens a quoted field too.
            field.text.clear();
            field.col = here_col + 1;
            quoted = Some((here_line, here_col));
        } else {
            field.text.push(c);
        }
    }
    if let Some((l, c)) = quoted {
        // The rest of the file is inside the quote: that record is the problem, not a tag.
        problems.add(l, c, msg!("tags-csv-unclosed-quote"));
        return out;
    }
    if !field.text.is_empty() || !record.is_empty() {
        if field.text.ends_with('\r') {
            field.text.pop();
        }
        record.push(field);
        out.push(record);
    }
    out
}

/// Reads a CSV tag table.
pub fn parse(text: &str, problems: &mut Problems<'_>) -> Vec<Tag> {
    let sep = separator(text);
    let rows = records(text, sep, problems);
    let blank = |r: &Vec<Field>| r.iter().all(|f| f.text.trim().is_empty());
    let note = |r: &Vec<Field>| {
        r.first().is_some_and(|f| f.text.trim_start().starts_with('#') || f.text.trim_start().starts_with("//"))
    };
    let mut rows = rows.into_iter().filter(|r| !blank(r) && !note(r)).peekable();
    // Column positions: name, address, type, comment.
    let mut cols: [Option<usize>; 4] = [Some(0), Some(1), Some(2), Some(3)];
    if let Some(first) = rows.peek() {
        let named: Vec<Option<Column>> = first.iter().map(|f| header_column(&f.text)).collect();
        if named.iter().flatten().count() >= 2 || named.first().copied().flatten() == Some(Column::Name) {
            cols = [None; 4];
            for (i, c) in named.iter().enumerate() {
                if let Some(c) = c {
                    let slot = &mut cols[*c as usize];
                    if slot.is_none() {
                        *slot = Some(i);
                    }
                }
            }
            let (l, c) = (first[0].line, first[0].col);
            rows.next();
            for (what, slot) in [("name", cols[0]), ("address", cols[1])] {
                if slot.is_none() {
                    problems.add(l, c, msg!("tags-csv-no-column", column = what));
                }
            }
            if cols[0].is_none() || cols[1].is_none() {
                return Vec::new();
            }
        }
    }
    let mut tags = Vec::new();
    for row in rows {
        let cell = |i: Option<usize>| i.and_then(|i| row.get(i));
        let row_at = (row[0].line, row[0].col);
        let name = cell(cols[0]);
        let address = cell(cols[1]);
        let name_text = name.map(|f| f.text.trim()).unwrap_or("");
        let (nl, nc) = name.map(|f| (f.line, f.col + lead(&f.text))).unwrap_or(row_at);
        if name_text.is_empty() {
            problems.add(nl, nc, msg!("tags-no-name"));
            continue;
        }
        let addr_text = address.map(|f| f.text.trim()).unwrap_or("");
        if addr_text.is_empty() {
            let (l, c) = address.map(|f| (f.line, f.col)).unwrap_or((nl, nc));
            problems.add(l, c, msg!("tags-no-address", name = name_text));
            continue;
        }
        if let Some(bad) = addr_text.find(|c: char| c.is_whitespace() || c == '/') {
            let f = address.unwrap();
            problems.add(
                f.line,
                f.col + lead(&f.text) + addr_text[..bad].chars().count(),
                msg!("tags-bad-address", name = name_text, address = addr_text),
            );
            continue;
        }
        let dtype = match cell(cols[2]) {
            None => TagType::Natural,
            Some(f) => match TagType::parse(&f.text) {
                Some(t) => t,
                None => {
                    problems.add(
                        f.line,
                        f.col + lead(&f.text),
                        msg!("tags-unknown-type", name = name_text, dtype = f.text.trim()),
                    );
                    continue;
                }
            },
        };
        let comment = cell(cols[3]).map(|f| f.text.trim().to_string()).unwrap_or_default();
        tags.push(Tag {
            name: name_text.to_string(),
            address: address_text(addr_text),
            dtype,
            comment,
            line: nl,
            column: nc,
        });
    }
    tags
}

/// The characters of leading white space (a field's text starts after them).
fn lead(s: &str) -> usize {
    s.chars().take_while(|c| c.is_whitespace()).count()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::DataType;

    fn read(text: &str) -> (Vec<Tag>, Vec<String>) {
        let mut p = Problems::new("t.csv");
        let t = parse(text, &mut p);
        p.list.sort_by_key(|p| (p.line, p.column));
        (t, p.list.iter().map(|p| p.to_string()).collect())
    }

    #[test]
    fn header_words_in_three_languages_and_any_order() {
        let (t, p) = read("Адрес;Имя;Тип;Комментарий\r\nVD200;Уровень_2;REAL;Уровень в баке 2\r\n");
        assert!(p.is_empty(), "{p:?}");
        assert_eq!(t[0].name, "Уровень_2");
        assert_eq!(t[0].address, "VD200");
        assert_eq!(t[0].dtype, TagType::Of(DataType::Real));
        assert_eq!(t[0].comment, "Уровень в баке 2");
        assert_eq!((t[0].line, t[0].column), (2, 7));
        let (t, p) = read("名称\t地址\t数据类型\t初始值\t注释\n电机_启动\t%MX0.3\tBOOL\t0\t启动按钮\n");
        assert!(p.is_empty(), "{p:?}");
        assert_eq!(
            (t[0].name.as_str(), t[0].address.as_str(), t[0].comment.as_str()),
            ("电机_启动", "M0.3", "启动按钮")
        );
    }

    #[test]
    fn no_header_means_positional_columns_and_quotes_hold_separators() {
        let (t, p) = read("Conveyor_Run,M0.3,BOOL,\"Belt, main \"\"A\"\"\"\n\n# a note\nTank2_Level,VD200\n");
        assert!(p.is_empty(), "{p:?}");
        assert_eq!(t.len(), 2);
        assert_eq!(t[0].comment, "Belt, main \"A\"");
        assert_eq!(t[1].dtype, TagType::Natural);
        assert_eq!((t[1].line, t[1].column), (4, 1));
    }

    #[test]
    fn problems_name_line_and_column() {
        let (_, p) = read("name,address,type\nA,VW0,FLOAT\nB,,INT\nC,V W0\n\"D,VW2\n");
        assert_eq!(
            p,
            vec![
                "t.csv:2:7: `A`: unknown type `FLOAT` (BOOL, BYTE, SINT, WORD, INT, DWORD, DINT, REAL; UINT, UDINT, USINT too)",
                "t.csv:3:3: `B` has no address",
                "t.csv:4:4: `C`: `V W0` is not an address (an address has no spaces and no `/TYPE`: VW0, M0.3, %MW10; the type goes in its own column)",
                "t.csv:5:1: a quote opened here is not closed (a quote inside a quoted field is written twice: \"\")",
            ]
        );
        let (_, p) = read("name;comment\nA;x\n");
        assert_eq!(
            p,
            vec!["t.csv:1:1: the header row has no address column (its words: name, address, type, comment)"]
        );
    }
}
