# Doxygen input filter for the option table's two headers (POSIX awk; mawk works).
#
# onetip/sensor_options.hpp: SensorOptions declares its fields by including
# the X-macro table onetip/sensor_option_table.hpp inside the struct. Doxygen
# does not expand an include inside a class, so this filter replaces that
# #include line with the declarations the table produces, each documented from
# its own row: the row's one-line doc, the `//` comment lines just above the
# row, its unit, range and default. The generated text stays on the include's
# line, and the #define/#undef of ONETIP_OPTION around it become empty lines,
# so the line numbers of the rest of the file are unchanged. The table is read
# from the same folder.
#
# onetip/sensor_option_table.hpp: only its file comment is kept (everything
# from its first preprocessor line on becomes empty lines): its rows are not
# declarations on their own, and they are documented as SensorOptions' fields.
#
# Usage (as Doxygen calls it): awk -f option_table_filter.awk FILE

function trim(s) {
  sub(/^[ \t]+/, "", s)
  sub(/[ \t]+$/, "", s)
  return s
}

function unquote(s) {
  s = trim(s)
  if (substr(s, 1, 1) == "\"" && substr(s, length(s), 1) == "\"") s = substr(s, 2, length(s) - 2)
  return s
}

# Splits the argument list `s` at the commas outside quotes and parentheses
# into args[1..n]; returns n.
function split_args(s, args,    n, i, c, depth, quoted, cur) {
  n = 0
  depth = 0
  quoted = 0
  cur = ""
  for (i = 1; i <= length(s); i++) {
    c = substr(s, i, 1)
    if (quoted) {
      if (c == "\\") {
        cur = cur c substr(s, i + 1, 1)
        i++
        continue
      }
      if (c == "\"") quoted = 0
    } else if (c == "\"") {
      quoted = 1
    } else if (c == "(") {
      depth++
    } else if (c == ")") {
      depth--
    } else if (c == "," && depth == 0) {
      args[++n] = trim(cur)
      cur = ""
      continue
    }
    cur = cur c
  }
  args[++n] = trim(cur)
  return n
}

# Net count of "(" minus ")" outside quotes.
function paren_balance(s,    i, c, b, quoted) {
  b = 0
  quoted = 0
  for (i = 1; i <= length(s); i++) {
    c = substr(s, i, 1)
    if (quoted) {
      if (c == "\\") i++
      else if (c == "\"") quoted = 0
    } else if (c == "\"") quoted = 1
    else if (c == "(") b++
    else if (c == ")") b--
  }
  return b
}

# Doxygen text must not close the comment or start a command by accident.
function doc_safe(s) {
  gsub(/\*\//, "* /", s)
  gsub(/@/, "\\@", s)
  gsub(/</, "\\<", s)
  gsub(/>/, "\\>", s)
  gsub(/#/, "\\#", s)
  return s
}

function unit_text(type, unit) {
  if (unit == "mm|deg") return "mm for dx, dy, dz; degrees for yaw, pitch, roll"
  if (unit == "") return (type == "bool" || type == "FilterKind") ? "" : "none (a count or plain factor)"
  return unit
}

function range_text(type, lo, hi) {
  if (type == "bool") return ""
  if (type == "FilterKind") return ""
  if (type == "AxisArray") return "every value in [" lo ", " hi "]"
  return "[" lo ", " hi "]"
}

function declaration(row, comment,    args, n, name, type, lo, hi, unit, doc, def, i, text, u, r) {
  n = split_args(row, args)
  name = args[1]
  type = args[2]
  lo = args[3]
  hi = args[4]
  unit = unquote(args[5])
  doc = unquote(args[6])
  def = args[7]
  for (i = 8; i <= n; i++) def = def ", " args[i]
  text = doc "."
  if (comment != "") text = text " " comment
  if (type == "AxisArray") text = text " Six values in Input6 order [dx, dy, dz, yaw, pitch, roll]."
  if (type == "FilterKind") text = text " One of FilterKind::none, FilterKind::moving_average, FilterKind::one_euro."
  u = unit_text(type, unit)
  r = range_text(type, lo, hi)
  text = text " Key `" name "` (options file, get()/set(), C struct onetip_options)."
  if (u != "") text = text " Unit: " u "."
  if (r != "") text = text " Valid: " r "."
  text = text " Default: " def "."
  return "/** " doc_safe(text) " */ " type " " name "{" def "};"
}

function expand_table(path,    line, comment, row, depth, out, status) {
  comment = ""
  row = ""
  depth = 0
  out = ""
  while ((status = (getline line < path)) > 0) {
    if (row != "") {
      row = row " " trim(line)
      depth += paren_balance(line)
      if (depth <= 0) {
        sub(/\)[ \t]*$/, "", row)
        out = out declaration(row, comment) " "
        row = ""
        comment = ""
      }
      continue
    }
    if (line ~ /^ONETIP_OPTION\(/) {
      sub(/^ONETIP_OPTION\(/, "", line)
      row = line
      depth = 1 + paren_balance(line)
      if (depth <= 0) {
        sub(/\)[ \t]*$/, "", row)
        out = out declaration(row, comment) " "
        row = ""
        comment = ""
      } else {
        row = line
      }
      continue
    }
    if (line ~ /^[ \t]*\/\/ ---/ || line ~ /^[ \t]*$/ || line ~ /^#/) {
      comment = ""
      continue
    }
    if (line ~ /^[ \t]*\/\//) {
      sub(/^[ \t]*\/\/[ \t]?/, "", line)
      comment = (comment == "") ? line : comment " " line
    }
  }
  if (status < 0) {
    print "option_table_filter.awk: cannot read " path > "/dev/stderr"
    exit 1
  }
  close(path)
  return out
}

FNR == 1 {
  dir = FILENAME
  if (!sub(/[^\/]*$/, "", dir)) dir = ""
  table_file = (FILENAME ~ /sensor_option_table\.hpp$/)
  in_rows = 0
}

table_file {
  if ($0 ~ /^#/) in_rows = 1
  print (in_rows ? "" : $0)
  next
}

/^#(define|undef)[ \t]+ONETIP_OPTION/ {
  print ""
  next
}

/^[ \t]*#[ \t]*include[ \t]+"onetip\/sensor_option_table\.hpp"/ {
  print expand_table(dir "sensor_option_table.hpp")
  next
}

{ print }
