//! Long display math set on lines that fit an A4 page (issue 27: a printed derivation has
//! no overfull lines). TeX never breaks a display, so a long formula is broken here:
//!
//! * a sum is broken before its `+` and `-` signs outside braces (also inside parentheses:
//!   a `\left( ... \right)` pair that ends up on two lines becomes `\Bigl( ... \Bigr)`), the
//!   lines filled greedily and set in an `align*` (`\allowdisplaybreaks` lets it cross pages);
//! * a fraction $\pm N / D$ too wide for the line gets its numerator (and denominator) broken
//!   the same way: stacked over the fraction bar when that stays short, else named,
//!   $x = -\nu/\delta$ with $\nu = \dots$, $\delta = \dots$ on their own lines;
//! * an integer longer than a line is stacked in rows of digits.
//!
//! Widths are estimated in points from the LaTeX source (11 pt type, display style): a
//! letter or digit about 5.5 pt, a binary sign with its spaces about 13 pt, sub- and
//! superscripts 0.7 of that, a fraction the wider of its parts.

use std::fmt::Write;

/// The width of a displayed line on A4 with 2 cm margins (170 mm = 483 pt), less a margin
/// for the estimate's error.
pub const TEXT_PT: f64 = 410.0;

/// Approximate typeset width of LaTeX math `t` in points (module docs).
///
/// ```
/// use exactlti::report::latex::lines::width_pt;
/// assert!(width_pt(r"\frac{a + b + c}{d}") < width_pt("a + b + c + d"));
/// assert!(width_pt("x^{2}") < width_pt("x2"));
/// ```
pub fn width_pt(t: &str) -> f64 {
    width_scaled(t.as_bytes(), 1.0)
}

/// The group `{...}` starting at `b[i] == b'{'`: its content's end (index of the closing
/// brace); `None` when unbalanced.
fn group_end(b: &[u8], i: usize) -> Option<usize> {
    let mut depth = 0i32;
    let mut j = i;
    while j < b.len() {
        match b[j] {
            b'\\' => j += 1,
            b'{' => depth += 1,
            b'}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(j);
                }
            }
            _ => {}
        }
        j += 1;
    }
    None
}

fn width_scaled(b: &[u8], scale: f64) -> f64 {
    let (mut w, mut i) = (0.0, 0usize);
    while i < b.len() {
        let c = b[i];
        if c == b'\\' {
            // a control word
            let mut j = i + 1;
            while j < b.len() && b[j].is_ascii_alphabetic() {
                j += 1;
            }
            let word = &b[i + 1..j];
            if j == i + 1 {
                // \, \; \! \\ \{ ...
                let sp = match b.get(j) {
                    Some(b',') => 3.0,
                    Some(b';') => 5.0,
                    Some(b'!') => -1.5,
                    _ => 5.5,
                };
                w += sp * scale;
                i = j + 1;
                continue;
            }
            if (word == b"frac" || word == b"dfrac" || word == b"tfrac")
                && b.get(j) == Some(&b'{')
                && let Some(e1) = group_end(b, j)
                && b.get(e1 + 1) == Some(&b'{')
                && let Some(e2) = group_end(b, e1 + 1)
            {
                let n = width_scaled(&b[j + 1..e1], scale);
                let d = width_scaled(&b[e1 + 2..e2], scale);
                w += n.max(d) + 4.0 * scale;
                i = e2 + 1;
                continue;
            }
            w += match word {
                b"left" | b"right" | b"mathit" | b"mathrm" | b"operatorname" | b"text"
                | b"mathbf" | b"displaystyle" | b"begin" | b"end" | b"Bigl" | b"Bigr" | b"bigl"
                | b"bigr" => 2.0,
                b"quad" => 11.0,
                b"qquad" => 22.0,
                b"cdot" | b"ne" | b"le" | b"ge" | b"mapsto" | b"to" => 13.0,
                _ => 6.0,
            } * scale;
            i = j;
            continue;
        }
        if (c == b'^' || c == b'_') && i + 1 < b.len() {
            if b[i + 1] == b'{'
                && let Some(e) = group_end(b, i + 1)
            {
                w += width_scaled(&b[i + 2..e], scale * 0.7);
                i = e + 1;
                continue;
            }
            w += 5.5 * scale * 0.7;
            i += 2;
            continue;
        }
        w += match c {
            b'{' | b'}' | b' ' | b'&' => 0.0,
            b'+' | b'-' | b'=' => 13.0,
            b',' | b';' => 4.5,
            b'(' | b')' | b'[' | b']' | b'|' => 4.3,
            _ => 5.5,
        } * scale;
        i += 1;
    }
    w
}

/// `body` split before every `+` / `-` sign (written ` + ` / ` - `) that is outside braces;
/// `\left` / `\right` pairs do not stop a split ([`fix_delims`] mends them per line).
fn pieces(body: &str) -> Vec<String> {
    let b = body.as_bytes();
    let (mut parts, mut cur, mut depth) = (vec![], String::new(), 0i32);
    let mut i = 0;
    while i < b.len() {
        let rest = &body[i..];
        if b[i] == b'\\' {
            // a control sequence (with an escaped brace) is copied whole
            let len = 1 + rest[1..]
                .chars()
                .take_while(|c| c.is_ascii_alphabetic())
                .count()
                .max(1)
                .min(rest.len() - 1);
            cur.push_str(&rest[..len]);
            i += len;
            continue;
        }
        if b[i] == b'{' {
            depth += 1;
        } else if b[i] == b'}' {
            depth -= 1;
        }
        if depth == 0 && (rest.starts_with(" + ") || rest.starts_with(" - ")) && !cur.is_empty() {
            parts.push(std::mem::take(&mut cur));
        }
        let ch = rest.chars().next().unwrap_or(' ');
        cur.push(ch);
        i += ch.len_utf8();
    }
    parts.push(cur);
    parts
}

/// On one line, a `\left` without its `\right` (or the reverse) becomes `\Bigl` (`\Bigr`):
/// TeX needs the pair within one line, a `\Bigl` stands alone.
fn fix_delims(line: &str) -> String {
    // positions of \left and \right tokens; match them with a stack
    let mut toks: Vec<(usize, bool)> = vec![];
    let mut i = 0;
    while let Some(p) = line[i..].find('\\') {
        let at = i + p;
        let rest = &line[at..];
        if rest.starts_with("\\left") && !rest[5..].starts_with(|c: char| c.is_ascii_alphabetic()) {
            toks.push((at, true));
        } else if rest.starts_with("\\right")
            && !rest[6..].starts_with(|c: char| c.is_ascii_alphabetic())
        {
            toks.push((at, false));
        }
        i = at + 1;
    }
    let mut stack: Vec<usize> = vec![];
    let mut lone: Vec<usize> = vec![];
    for (k, &(_, open)) in toks.iter().enumerate() {
        if open {
            stack.push(k);
        } else if stack.pop().is_none() {
            lone.push(k);
        }
    }
    lone.extend(stack);
    if lone.is_empty() {
        return line.to_string();
    }
    let mut out = String::new();
    let mut last = 0;
    let mut lone_pos: Vec<(usize, bool)> = lone.iter().map(|&k| toks[k]).collect();
    lone_pos.sort_unstable();
    for (at, open) in lone_pos {
        out.push_str(&line[last..at]);
        out.push_str(if open { "\\Bigl" } else { "\\Bigr" });
        last = at + if open { 5 } else { 6 };
    }
    out.push_str(&line[last..]);
    out
}

/// The lines of a long sum, each at most `max` points wide where the pieces allow (a piece
/// wider than that stays one line, its long integers stacked).
pub fn break_sum(body: &str, max: f64) -> Vec<String> {
    let mut lines: Vec<String> = vec![];
    for p in pieces(body) {
        match lines.last_mut() {
            Some(l) if width_pt(l) + width_pt(&p) <= max => l.push_str(&p),
            _ => lines.push(p),
        }
    }
    lines
        .iter()
        .map(|l| {
            let l = fix_delims(l.trim_start());
            if width_pt(&l) > max {
                stack_digits(&l, max)
            } else {
                l
            }
        })
        .collect()
}

/// `[-]\frac{N}{D}` as the whole of `body`: `(sign, N, D)`.
fn as_fraction(body: &str) -> Option<(&str, &str, &str)> {
    let (sign, rest) = match body.strip_prefix('-') {
        Some(r) => ("-", r.trim_start()),
        None => ("", body),
    };
    let rest = rest
        .strip_prefix("\\frac")
        .or_else(|| rest.strip_prefix("\\dfrac"))?;
    let b = rest.as_bytes();
    if b.first() != Some(&b'{') {
        return None;
    }
    let e1 = group_end(b, 0)?;
    if b.get(e1 + 1) != Some(&b'{') {
        return None;
    }
    let e2 = group_end(b, e1 + 1)?;
    (e2 + 1 == b.len()).then(|| (sign, &rest[1..e1], &rest[e1 + 2..e2]))
}

/// Every run of digits wider than `max` points stacked in rows (a one-column `array`: TeX
/// does not break a number).
fn stack_digits(t: &str, max: f64) -> String {
    let per_row = ((max / 5.5) as usize).clamp(16, 72);
    let mut out = String::new();
    let mut run = String::new();
    let flush = |out: &mut String, run: &mut String| {
        if run.len() > per_row {
            let rows: Vec<&str> = run
                .as_bytes()
                .chunks(per_row)
                .map(|c| std::str::from_utf8(c).unwrap_or(""))
                .collect();
            let _ = write!(
                out,
                r"\begin{{array}}{{@{{}}l@{{}}}}{}\end{{array}}",
                rows.join(r" \\ ")
            );
        } else {
            out.push_str(run);
        }
        run.clear();
    };
    for c in t.chars() {
        if c.is_ascii_digit() {
            run.push(c);
        } else {
            flush(&mut out, &mut run);
            out.push(c);
        }
    }
    flush(&mut out, &mut run);
    out
}

/// The lines of an `align*`: the first after `&=`, the others indented.
fn aligned_rows(name: &str, lines: &[String]) -> String {
    format!("{name} &= {}", lines.join(" \\\\\n&\\quad "))
}

/// Lines a numerator may take over a fraction bar before it is named instead.
const STACKED_LINES: usize = 3;

/// The fractions of `body` outside braces wider than `max` points replaced by
/// `\kappa_{j}` (`j` from `first`): the new body and the `(symbol, fraction)` pairs.
fn name_wide_fractions(body: &str, max: f64, first: usize) -> (String, Vec<(String, String)>) {
    let b = body.as_bytes();
    let (mut out, mut named) = (String::new(), vec![]);
    let (mut i, mut last, mut depth) = (0usize, 0usize, 0i32);
    while i < b.len() {
        match b[i] {
            b'\\' => {
                let rest = &body[i..];
                let len = if rest.starts_with("\\frac{") {
                    5
                } else if rest.starts_with("\\dfrac{") {
                    6
                } else {
                    i += 2;
                    continue;
                };
                if depth == 0
                    && let Some(e1) = group_end(b, i + len)
                    && b.get(e1 + 1) == Some(&b'{')
                    && let Some(e2) = group_end(b, e1 + 1)
                {
                    let frac = &body[i..=e2];
                    if width_pt(frac) > max {
                        let sym = format!("\\kappa_{{{}}}", first + named.len());
                        out.push_str(&body[last..i]);
                        out.push_str(&sym);
                        named.push((sym, frac.to_string()));
                        last = e2 + 1;
                    }
                    i = e2 + 1;
                    continue;
                }
                i += len;
                continue;
            }
            b'{' => depth += 1,
            b'}' => depth -= 1,
            _ => {}
        }
        i += 1;
    }
    out.push_str(&body[last..]);
    (out, named)
}

/// `name = body` in display math, fitted to the A4 text width (module docs).
///
/// ```
/// use exactlti::report::latex::lines::display;
/// let long: Vec<String> = (1..40).map(|i| format!("{i} a^{{{i}}}")).collect();
/// let mut s = String::new();
/// display(&mut s, "x", &format!("-\\frac{{{}}}{{b}}", long.join(" + ")));
/// assert!(s.contains("align*") && s.contains("\\nu &="));
/// ```
pub fn display(s: &mut String, name: &str, body: &str) {
    display_sub(s, name, body, "");
}

/// [`display`] with `sub` the subscript of the names it introduces ($\nu$, $\delta$).
fn display_sub(s: &mut String, name: &str, body: &str, sub: &str) {
    let room = TEXT_PT - width_pt(name) - 20.0;
    if width_pt(body) <= room {
        let _ = writeln!(s, "\\[ {name} = {body} \\]");
        return;
    }
    if let Some((sign, num, den)) = as_fraction(body) {
        return fraction(s, name, (sign, num, den), sub);
    }
    // a fraction too wide to sit in a line of the sum: named, set below
    if pieces(body).iter().any(|p| width_pt(p) > room) {
        let (short, named) = name_wide_fractions(body, room / 2.0, 1);
        if !named.is_empty() {
            display_sub(s, name, &short, sub);
            for (i, (sym, frac)) in named.iter().enumerate() {
                display_sub(s, sym, frac, &format!("{}", i + 1));
            }
            return;
        }
    }
    let lines = break_sum(body, room);
    if lines.len() == 1 {
        let _ = writeln!(s, "\\[ {name} = {} \\]", lines[0]);
        return;
    }
    let _ = writeln!(s, "\\begin{{align*}}\n{}", aligned_rows(name, &lines));
    s.push_str("\\end{align*}\n");
}

/// `name = sign N / D` too wide for one line: the numerator stacked over the bar when that
/// stays short, else `name = sign nu / delta` with $\nu$, $\delta$ on lines of their own.
fn fraction(s: &mut String, name: &str, (sign, num, den): (&str, &str, &str), sub: &str) {
    let room = TEXT_PT - width_pt(name) - 20.0;
    let (wn, wd) = (width_pt(num), width_pt(den));
    let nl = break_sum(num, room - 20.0);
    if wd <= room - 10.0 && nl.len() <= STACKED_LINES {
        let rows = nl.join(r" \\ \quad ");
        let _ = writeln!(
            s,
            "\\[ {name} = {sign}\\frac{{\\begin{{array}}{{@{{}}l@{{}}}}{rows}\\end{{array}}}}{{{den}}} \\]"
        );
        return;
    }
    let sub = if sub.is_empty() {
        String::new()
    } else {
        format!("_{{{sub}}}")
    };
    let (nu, delta) = (format!("\\nu{sub}"), format!("\\delta{sub}"));
    let short_den = wd <= room / 2.0;
    let short_num = wn <= room / 2.0;
    let n_sym = if short_num { num } else { nu.as_str() };
    let d_sym = if short_den { den } else { delta.as_str() };
    let _ = writeln!(
        s,
        "\\begin{{align*}}\n{name} &= {sign}\\frac{{{n_sym}}}{{{d_sym}}},\\quad\\text{{where}}"
    );
    if !short_num {
        let _ = write!(
            s,
            "\\\\\n{}",
            aligned_rows(&nu, &break_sum(num, TEXT_PT - 40.0))
        );
    }
    if !short_den {
        let _ = write!(
            s,
            "\\\\\n{}",
            aligned_rows(&delta, &break_sum(den, TEXT_PT - 40.0))
        );
    }
    s.push_str("\n\\end{align*}\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairs_split_across_lines_become_big_delimiters() {
        assert_eq!(fix_delims(r"\left(a + b"), r"\Bigl(a + b");
        assert_eq!(fix_delims(r"c\right) s^{2}"), r"c\Bigr) s^{2}");
        assert_eq!(
            fix_delims(r"\left(a\right) + \left(b"),
            r"\left(a\right) + \Bigl(b"
        );
    }

    #[test]
    fn a_sum_is_split_outside_braces_only() {
        let p = pieces(r"\frac{a + b}{c} + d - e");
        assert_eq!(p, [r"\frac{a + b}{c}", " + d", " - e"]);
        assert_eq!(as_fraction(r"-\frac{a + b}{c}"), Some(("-", "a + b", "c")));
        assert_eq!(as_fraction(r"\frac{a}{c} + 1"), None);
    }

    #[test]
    fn every_line_of_a_long_sum_fits() {
        let body: Vec<String> = (1..200)
            .map(|i| format!("{i} \\mathit{{cf}}^{{{i}}} m"))
            .collect();
        let lines = break_sum(&body.join(" + "), TEXT_PT);
        assert!(lines.len() > 5);
        assert!(lines.iter().all(|l| width_pt(l) <= TEXT_PT));
        // nothing lost: the pieces joined again are the sum
        let again: String = lines.join(" ");
        assert_eq!(again.matches('+').count(), 198);
    }

    #[test]
    fn wide_fractions_inside_a_sum_are_named() {
        let long: Vec<String> = (1..60).map(|i| format!("{i} a^{{{i}}}")).collect();
        let f = format!("\\frac{{{}}}{{b}}", long.join(" + "));
        let body = format!("\\left({f}\\right) t + \\left({f}\\right)");
        let (short, named) = name_wide_fractions(&body, 200.0, 1);
        assert_eq!(
            short,
            r"\left(\kappa_{1}\right) t + \left(\kappa_{2}\right)"
        );
        assert_eq!(named.len(), 2);
        let mut s = String::new();
        display(&mut s, "x", &body);
        assert!(s.contains(r"\nu_{2} &="), "{s}");
        for line in s.lines() {
            assert!(width_pt(line) <= TEXT_PT + 40.0, "{line}");
        }
    }
}
