//! The README's parameter table says what the one declaration of each parameter
//! (`engine/src/params.rs`) says: every parameter is listed with its valid range and a source.

use snooker_engine::params::PARAMS;

#[test]
fn the_readme_lists_every_parameter_with_its_range_and_source() {
    let readme = include_str!("../README.md");
    for info in PARAMS {
        let name = format!("`{}`", info.name);
        let range = info.range.to_string();
        let row = readme
            .lines()
            .filter(|l| l.starts_with('|'))
            .find(|l| {
                let cells: Vec<&str> = l.split('|').map(str::trim).collect();
                cells.len() > 5 && cells[1].contains(&name) && cells[4].starts_with(&range)
            })
            .unwrap_or_else(|| panic!("README: no parameter row for {name} with range {range}"));
        let source = row
            .trim_end_matches('|')
            .rsplit('|')
            .next()
            .unwrap_or("")
            .trim();
        assert!(!source.is_empty(), "README: no source for {name}: {row}");
    }
}
