# Sourced by the benchmark scripts. program NAME: the path of NAME built in "$build" (the build tree's
# own bin/), never a staged copy (the packages' trees under _CPack_Packages hold older builds).
program() {
  local root found
  root=$(cd "$build" && pwd) || exit 1 # absolute, without trailing slashes, so that the prune matches
  found=$(find "$root" -path "$root/_CPack_Packages" -prune -o -name "$1" -type f -perm -u+x -print | head -n 1)
  [ -n "$found" ] || { echo "no $1 in $build" >&2; exit 1; }
  echo "$found"
}
