//! What clap's bash completion script leaves out: a scenario file after
//! `reach run`, `watch`, `check` or `test` completes to `.reach` files and
//! directories (clap's script offers the options there instead).

/// The subcommands whose operands are scenario files (or, for `test`,
/// directories of them).
const SCENARIO_COMMANDS: [&str; 4] = ["run", "watch", "check", "test"];

/// Bash to append to clap's script: a completion function that completes
/// scenario files where an operand is expected and leaves every other
/// word (an option, or an option's value) to clap's `_reach`.
pub fn bash_scenario_files(command: &clap::Command) -> String {
    let valued: Vec<String> = command
        .get_subcommands()
        .filter(|s| SCENARIO_COMMANDS.contains(&s.get_name()))
        .flat_map(|s| s.get_arguments())
        .chain(command.get_arguments())
        .filter(|a| !a.is_positional() && a.get_action().takes_values())
        .flat_map(|a| {
            let long = a.get_long().map(|l| format!("--{l}"));
            let short = a.get_short().map(|c| format!("-{c}"));
            long.into_iter().chain(short)
        })
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect();
    format!(
        r#"
# Scenario files: after `reach {commands}`, a word that is not an option
# nor an option's value completes to .reach files and directories.
_reach_scenarios() {{
    local cur="${{COMP_WORDS[COMP_CWORD]}}" prev="${{COMP_WORDS[COMP_CWORD-1]}}"
    case "${{COMP_WORDS[1]}}" in
        {alternatives})
            if [[ ${{COMP_CWORD}} -ge 2 && "${{cur}}" != -* && " {valued} " != *" ${{prev%%=*}} "* ]]; then
                compopt -o filenames 2>/dev/null
                COMPREPLY=( $(compgen -f -X '!*.reach' -- "${{cur}}") $(compgen -d -- "${{cur}}") )
                return 0
            fi
            ;;
    esac
    _reach "$@"
}}
complete -F _reach_scenarios -o nosort -o bashdefault -o default reach 2>/dev/null \
    || complete -F _reach_scenarios -o bashdefault -o default reach
"#,
        commands = SCENARIO_COMMANDS.join("`, `"),
        alternatives = SCENARIO_COMMANDS.join("|"),
        valued = valued.join(" "),
    )
}
