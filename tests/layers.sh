#!/usr/bin/env bash
# The floors hold: every #include "<room>/..." in engine/, render/, report/ and app/
# is allowed by tests/layers.txt (its room, the rooms on its room's line, or the
# headers on its own file's line). Usage: layers.sh SOURCE_DIR [TABLE]. Exit 0 when
# every include is allowed, 1 naming each one that is not (and any folder or table
# entry the table does not know), 2 on bad usage.
set -u
set -f  # the table's room/* entries are patterns of ours, not file globs
root=${1:?usage: layers.sh SOURCE_DIR [TABLE]}
cd "$root" || exit 2
table=${2:-tests/layers.txt}
[ -f "$table" ] || { echo "layers: no table $table" >&2; exit 2; }
rooms=(engine render report app)  # the folders checked; an include of another is not a room's

declare -A allowed=()  # room or file -> what it may include, space-separated
status=0
line_no=0
while IFS= read -r line; do
  line_no=$((line_no + 1))
  line=${line%%#*}
  read -r -a fields <<<"$line"
  ((${#fields[@]})) || continue
  key=${fields[0]}
  if [ ! -e "$key" ]; then
    echo "layers: $table:$line_no: $key does not exist" >&2
    status=1
  fi
  entries=()
  for entry in "${fields[@]:1}"; do
    [ "$entry" = "-" ] && continue
    if [ ! -e "${entry%/\*}" ]; then
      echo "layers: $table:$line_no: $key may include $entry, which does not exist" >&2
      status=1
    fi
    entries+=("$entry")
  done
  allowed[$key]="${entries[*]}"
done <"$table"

# Whether a file of room `room` (file `file`) may include `target`.
may_include() {
  local room=$1 file=$2 target=$3 target_room entry
  target_room=${target%/*}
  [ "$target_room" = "$room" ] && return 0
  for entry in ${allowed[$room]} ${allowed[$file]:-}; do
    case $entry in
      "$target" | "$target_room") return 0 ;;
      */\*) [ "$target_room" = "${entry%/\*}" ] || [[ $target_room == "${entry%\*}"* ]] && return 0 ;;
    esac
  done
  return 1
}

files=0
includes=0
while IFS= read -r file; do
  room=${file%/*}
  files=$((files + 1))
  if [ -z "${allowed[$room]+set}" ]; then
    echo "layers: $file: its room $room has no line in $table" >&2
    status=1
    continue
  fi
  while IFS=: read -r number text; do
    [[ $text =~ ^[[:space:]]*#[[:space:]]*include[[:space:]]*\"([^\"]+)\" ]] || continue
    target=${BASH_REMATCH[1]}
    case ${target%%/*} in engine | render | report | app) ;; *) continue ;; esac
    [[ $target == */* ]] || continue
    includes=$((includes + 1))
    if ! may_include "$room" "$file" "$target"; then
      read -r -a what <<<"$room ${allowed[$room]} ${allowed[$file]:-}"
      echo "layers: $file:$number includes $target; $file may include: ${what[*]} ($table)" >&2
      status=1
    fi
  done < <(grep -n 'include' "$file")
done < <(find "${rooms[@]}" -type f \( -name '*.hpp' -o -name '*.cpp' -o -name '*.h' \) | sort)

[ "$status" -eq 0 ] && echo "layers: all $includes includes of $files files keep to $table"
exit "$status"
