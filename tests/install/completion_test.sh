#!/bin/bash
# The completion files against the built alp85 (no package needed): the window's test hooks
# (--click, --click-line, --debug-command) hidden from --help are not offered, the options a user
# has are. Usage: completion_test.sh ALP85 SOURCE_DIR
set -euo pipefail
alp85=$1 src=$2
fail() { echo "FAIL: $*" >&2; exit 1; }
checked=0

if [ -f /usr/share/bash-completion/bash_completion ]; then
  complete_words() {  # the words bash would offer for the command line "$*"
    bash "$(dirname "$0")/complete_words.sh" "$src/scripts/packaging/completion/alp85.bash" "$@"
  }
  got=$(complete_words "$alp85" gui --)
  grep -qx -- --screenshot <<<"$got" || fail "bash: gui -- does not offer --screenshot: $got"
  grep -qx -- --debug <<<"$got" || fail "bash: gui -- does not offer --debug: $got"
  ! grep -qE -- '^--(click|click-line|debug-command)$' <<<"$got" || fail "bash: gui -- offers a test hook: $got"
  echo "bash: gui -- offers $(wc -l <<<"$got") options, no test hook"
  checked=$((checked + 1))
else
  echo "bash not checked: bash-completion is not installed (scripts/setup.sh --tests installs it)"
fi

if command -v fish >/dev/null; then
  dir=$(mktemp -d)
  trap 'rm -rf "$dir"' EXIT
  cp "$src/scripts/packaging/completion/alp85.fish" "$dir/alp85.fish"
  # fish completes the command named alp85: a link to the built one, first on PATH.
  mkdir "$dir/bin" && ln -s "$alp85" "$dir/bin/alp85"
  got=$(PATH="$dir/bin:$PATH" fish --no-config -c "set fish_complete_path $dir; complete -C 'alp85 gui --'" | cut -f1)
  grep -qx -- --screenshot <<<"$got" || fail "fish: gui -- does not offer --screenshot: $got"
  ! grep -qE -- '^--(click|click-line|debug-command)$' <<<"$got" || fail "fish: gui -- offers a test hook: $got"
  echo "fish: gui -- offers $(wc -l <<<"$got") options, no test hook"
  checked=$((checked + 1))
else
  echo "fish not checked: fish is not installed (scripts/setup.sh --tests installs it)"
fi
[ "$checked" -gt 0 ] || echo "SKIP: neither bash-completion nor fish is installed"
