//! The book says what the code does: the parameter table of the "Physics and sources" page
//! (docs/physics.md) says what the one declaration of each parameter (`engine/src/params.rs`)
//! says, and the "Embedding" page's example (docs/embedding.md includes
//! `scene/examples/embedding.rs`) runs.

use snooker_engine::params::PARAMS;

#[path = "../scene/examples/embedding.rs"]
mod embedding;

#[test]
fn the_physics_page_lists_every_parameter_with_its_range_and_source() {
    let page = include_str!("../docs/physics.md");
    for info in PARAMS {
        let name = format!("`{}`", info.name);
        let range = info.range.to_string();
        let row = page
            .lines()
            .filter(|l| l.starts_with('|'))
            .find(|l| {
                let cells: Vec<&str> = l.split('|').map(str::trim).collect();
                cells.len() > 5 && cells[1].contains(&name) && cells[4].starts_with(&range)
            })
            .unwrap_or_else(|| {
                panic!("docs/physics.md: no parameter row for {name} with range {range}")
            });
        let source = row
            .trim_end_matches('|')
            .rsplit('|')
            .next()
            .unwrap_or("")
            .trim();
        assert!(
            !source.is_empty(),
            "docs/physics.md: no source for {name}: {row}"
        );
    }
}

#[test]
fn the_embedding_page_shows_the_example_that_runs() {
    let page = include_str!("../docs/embedding.md");
    assert!(
        page.contains("{{#include ../scene/examples/embedding.rs}}"),
        "docs/embedding.md must include scene/examples/embedding.rs whole"
    );
    embedding::main().expect("the embedding example runs");
}
