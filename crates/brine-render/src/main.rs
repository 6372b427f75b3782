//! The `brine` command. All logic lives in [`brine_render::cli`].

fn main() -> std::process::ExitCode {
    brine_render::cli::main()
}
