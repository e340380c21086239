//! The README's C and C++ examples are the files the C tests compile and run.

#[test]
fn readme_examples_are_the_tested_files() {
    let readme = include_str!("../README.md");
    for (file, lang) in [
        (include_str!("../c-tests/examples/example.c"), "```c\n"),
        (include_str!("../c-tests/examples/example.cpp"), "```cpp\n"),
        (include_str!("../c-tests/examples/elements.cpp"), "```cpp\n"),
        (include_str!("../c-tests/examples/repair.c"), "```c\n"),
        (include_str!("../c-tests/examples/repair.cpp"), "```cpp\n"),
    ] {
        let block = format!("{lang}{file}```");
        assert!(
            readme.contains(&block),
            "README.md lacks the tested {lang} example verbatim"
        );
    }
    let first = readme
        .lines()
        .filter(|l| !l.trim().is_empty())
        .nth(2)
        .unwrap_or("");
    assert!(
        first.starts_with("cargo run") && first.contains("info"),
        "README starts with the main command"
    );
    assert!(
        readme.contains("bash scripts/test.sh"),
        "README names the test command"
    );
}
