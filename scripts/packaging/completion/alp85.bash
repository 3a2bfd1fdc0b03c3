# Bash completion for ALP85's programs: alp85 (commands, options, firmware names, files), asm85 and
# pisa-asm. The commands and options are read from the program's own --help as it completes, so
# completion cannot drift from the program. Installed as
# share/bash-completion/completions/{alp85,asm85,pisa-asm}.

# The built-in firmware (alp85 run --firmware, debug, gui; tests/install checks this list).
_alp85_firmware="monitor thesis thesis-fixed master"

# From a CLI11 --help text on stdin: its options; the options that take a value; its commands.
_alp85_options() { awk '/^ +-/ { n = split($1, a, ","); for (i = 1; i <= n; i++) if (a[i] ~ /^-/) print a[i] }'; }
_alp85_valued() { awk '/^ +-/ && $2 ~ /^[A-Z]/ { n = split($1, a, ","); for (i = 1; i <= n; i++) if (a[i] ~ /^-/) print a[i] }'; }
_alp85_commands() { awk '/^Subcommands:/ { s = 1; next } s && /^  [a-z]/ { print $1; next } s && !/^ / { s = 0 }'; }

_alp85() {
    local cur prev words cword
    _init_completion || return
    local prog=${words[0]##*/}

    # The commands typed so far (alp85 bench cpu), skipping options and their values.
    local -a path=()
    local help i w skip=0
    help=$("${words[0]}" --help 2>/dev/null) || return
    for ((i = 1; i < cword; i++)); do
        w=${words[i]}
        if ((skip)); then skip=0; continue; fi
        if [[ $w == -* ]]; then
            [[ $w != *=* ]] && grep -qxF -- "$w" <<<"$(_alp85_valued <<<"$help")" && skip=1
            continue
        fi
        if grep -qxF -- "$w" <<<"$(_alp85_commands <<<"$help")"; then
            path+=("$w")
            help=$("${words[0]}" "${path[@]}" --help 2>/dev/null) || return
        fi
    done
    local cmd="$prog ${path[*]}"
    cmd=${cmd% }

    # The value of an option.
    if [[ $prev == -* ]] && grep -qxF -- "$prev" <<<"$(_alp85_valued <<<"$help")"; then
        case $prev in
            --firmware) COMPREPLY=($(compgen -W "$_alp85_firmware" -- "$cur")) ;;
            --motor) COMPREPLY=($(compgen -W "ideal physical" -- "$cur")) ;;
            --cpu)
                if [[ $prog == asm85 ]]; then COMPREPLY=($(compgen -W "8080 8085 8085u" -- "$cur"))
                else COMPREPLY=($(compgen -W "8080 8085" -- "$cur")); fi ;;
            --speed) COMPREPLY=($(compgen -W "0.1 1 10 100 max" -- "$cur")) ;;
            -I | --include | --out-dir) _filedir -d ;;
            --keys | --for | --boot | -D | --define | --from | --to | --org | --bin-start | --bin-end | \
                --fill | --max-tstates | --trace-last | --port | --seconds | --name-length | --click | -j | --jobs) ;;
            *) _filedir ;;
        esac
        return
    fi

    if [[ $cur == -* ]]; then
        COMPREPLY=($(compgen -W "$(_alp85_options <<<"$help")" -- "$cur"))
        [[ ${COMPREPLY-} == *= ]] && compopt -o nospace
        return
    fi
    local commands
    commands=$(_alp85_commands <<<"$help")
    if [[ -n $commands ]]; then
        COMPREPLY=($(compgen -W "$commands" -- "$cur"))
        return
    fi

    # The command's files.
    case $cmd in
        "alp85 run" | "alp85 debug" | "alp85 gui")
            _filedir '@(asm|hex|bin|ASM|HEX|BIN)'
            COMPREPLY+=($(compgen -W "$_alp85_firmware" -- "$cur")) ;;
        "alp85 script") _filedir '@(alp|ALP)' ;;
        "alp85 cpm") _filedir '@(com|COM)' ;;
        "alp85 disasm") _filedir '@(hex|bin|com|asm|HEX|BIN|COM|ASM)' ;;
        "alp85 gcode") _filedir '@(nc|ngc|gcode|NC|NGC)' ;;
        "alp85 pisa") _filedir '@(tape|TAPE)' ;;
        asm85) _filedir '@(asm|mac|inc|a85|ASM|MAC|INC|A85)' ;;
        pisa-asm) _filedir '@(pasm|PASM)' ;;
        alp85*) ;;
        *) _filedir ;;
    esac
} && complete -F _alp85 alp85 asm85 pisa-asm
