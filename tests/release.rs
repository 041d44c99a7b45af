//! The release archives (`.ci/release`) hold what a user needs beside the program: README,
//! both licence files, the changelog, the man page the program itself prints, the shell
//! completions (in the zip, the ones plcsh.exe makes, with Windows words) and the user guide;
//! and they are reproducible: plcsh.exe's header holds SOURCE_DATE_EPOCH, and packing the same
//! programs twice gives the same bytes. Checked by packing the builds at hand (the debug builds, so
//! it is fast: `PLCSH_RELEASE_*_EXE`, with `PLCSH_RELEASE_ANY_LINUX` for the Linux program not
//! being the static build) and listing both archives.
//!
//! Needs the Windows build (`target/x86_64-pc-windows-gnu/debug/plcsh.exe`, or
//! `PLCSH_RELEASE_WINDOWS_EXE`), the MinGW tools and Wine; the Windows stage of CI runs it after its
//! build with `PLCSH_RELEASE_TEST=1`, which makes a missing one a failure. Unix only (the
//! script is bash).

#![cfg(unix)]

mod common;
use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn windows_exe() -> Option<PathBuf> {
    let p = std::env::var_os("PLCSH_RELEASE_WINDOWS_EXE")
        .map(PathBuf::from)
        .unwrap_or_else(|| root().join("target/x86_64-pc-windows-gnu/debug/plcsh.exe"));
    let works = |tool: &str| Command::new(tool).arg("--version").output().is_ok_and(|o| o.status.success());
    // Wine runs plcsh.exe to make the zip's completions.
    let tools = works("x86_64-w64-mingw32-strip") && works("wine");
    (p.is_file() && tools).then_some(p)
}

fn version() -> String {
    let out = Command::new(common::bin()).arg("--version").output().unwrap();
    String::from_utf8_lossy(&out.stdout).split_whitespace().nth(1).unwrap().to_string()
}

/// The release's time (SOURCE_DATE_EPOCH): archived files and plcsh.exe's header carry it.
const EPOCH: u32 = 1_700_000_000;

/// Runs `.ci/release` into a folder of the test's own (`run` tells two runs apart); the folder.
fn release(win: &Path, run: u32) -> PathBuf {
    let dist = std::env::temp_dir().join(format!("plcsh-release-test-{}-{run}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dist);
    let out = Command::new(root().join(".ci/release"))
        .env("PLCSH_RELEASE_WINDOWS_EXE", win)
        .env("PLCSH_RELEASE_LINUX_EXE", common::bin())
        .env("PLCSH_RELEASE_ANY_LINUX", "1")
        .env("PLCSH_RELEASE_DIST", &dist)
        .env("SOURCE_DATE_EPOCH", EPOCH.to_string())
        .output()
        .expect(".ci/release runs");
    assert!(
        out.status.success(),
        ".ci/release failed:\n{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    dist
}

fn lines(out: std::process::Output) -> Vec<String> {
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).lines().map(|l| l.trim_end_matches('/').to_string()).collect()
}

#[test]
fn the_archives_hold_the_program_licences_changelog_man_page_and_completions() {
    let Some(win) = windows_exe() else {
        assert!(
            std::env::var_os("PLCSH_RELEASE_TEST").is_none(),
            "PLCSH_RELEASE_TEST is set: the Windows build, MinGW and Wine must be here"
        );
        common::skipped("the Windows build, MinGW and Wine (the Windows stage of CI: .ci/windows)");
        return;
    };
    let dist = release(&win, 1);
    let v = version();
    let zip = dist.join(format!("plcsh-{v}-x86_64-pc-windows-gnu.zip"));
    let tar = dist.join(format!("plcsh-{v}-x86_64-unknown-linux-gnu.tar.gz"));
    let listed_zip = lines(
        Command::new("python3")
            .args(["-c", "import sys, zipfile; print('\\n'.join(zipfile.ZipFile(sys.argv[1]).namelist()))"])
            .arg(&zip)
            .output()
            .unwrap(),
    );
    let listed_tar = lines(Command::new("tar").arg("-tzf").arg(&tar).output().unwrap());
    for (listed, triple, program) in
        [(&listed_zip, "x86_64-pc-windows-gnu", "plcsh.exe"), (&listed_tar, "x86_64-unknown-linux-gnu", "plcsh")]
    {
        let dir = format!("plcsh-{v}-{triple}");
        for f in [
            program,
            "README.md",
            "LICENSE-MIT",
            "LICENSE-APACHE",
            "CHANGELOG.md",
            "plcsh.1",
            "completions/plcsh.bash",
            "completions/_plcsh",
            "completions/plcsh.fish",
            "completions/_plcsh.ps1",
            "docs/windows.md",
        ] {
            let want = format!("{dir}/{f}");
            assert!(listed.contains(&want), "{want} is not in the archive: {listed:?}");
        }
        assert!(listed.iter().all(|l| l.starts_with(&dir)), "everything under {dir}/: {listed:?}");
    }
    // The man page is the program's own (`plcsh man`), and the program is the one given, its
    // debug info stripped.
    let man = Command::new("tar")
        .arg("-xzOf")
        .arg(&tar)
        .arg(format!("plcsh-{v}-x86_64-unknown-linux-gnu/plcsh.1"))
        .output()
        .unwrap();
    let ours = Command::new(common::bin()).args(["--state", "none", "man"]).output().unwrap();
    let text = String::from_utf8_lossy(&man.stdout);
    assert!(text.lines().any(|l| l.starts_with(".TH PLCSH 1")), "a man page: {text:.300}");
    assert!(man.stdout == ours.stdout, "plcsh.1 is `plcsh man`'s output");
    let sums = std::fs::read_to_string(dist.join("SHA256SUMS")).unwrap();
    assert_eq!(sums.lines().count(), 2, "{sums}");
    let size = |p: &Path| std::fs::metadata(p).unwrap().len();
    assert!(size(&zip) < size(&win), "the .exe in the zip is stripped and compressed");

    // The zip's completions are plcsh.exe's own: their help texts name Windows paths
    // (core::platform::words), the tarball's the Linux program's.
    let unzip = |name: &str| {
        let out = Command::new("python3")
            .args([
                "-c",
                "import sys, zipfile; sys.stdout.buffer.write(zipfile.ZipFile(sys.argv[1]).read(sys.argv[2]))",
            ])
            .arg(&zip)
            .arg(format!("plcsh-{v}-x86_64-pc-windows-gnu/{name}"))
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        out.stdout
    };
    let ps1 = String::from_utf8(unzip("completions/_plcsh.ps1")).unwrap();
    assert!(ps1.contains(r"%APPDATA%\plcsh\config\devices.toml") && !ps1.contains("~/.config"), "{ps1:.2000}");
    let tar_ps1 = Command::new("tar")
        .arg("-xzOf")
        .arg(&tar)
        .arg(format!("plcsh-{v}-x86_64-unknown-linux-gnu/completions/_plcsh.ps1"))
        .output()
        .unwrap();
    assert!(
        !String::from_utf8_lossy(&tar_ps1.stdout).contains("%APPDATA%"),
        "the Linux program's words in the tarball"
    );

    // Reproducible: the exe's header holds the release's time, not the time it was stripped
    // (PE header: the COFF header at the offset in 0x3C, TimeDateStamp 8 bytes in), and a
    // second run gives the same bytes.
    let exe = unzip("plcsh.exe");
    let pe = u32::from_le_bytes(exe[0x3C..0x40].try_into().unwrap()) as usize;
    assert_eq!(&exe[pe..pe + 4], b"PE\0\0");
    assert_eq!(u32::from_le_bytes(exe[pe + 8..pe + 12].try_into().unwrap()), EPOCH, "plcsh.exe's TimeDateStamp");
    let again = release(&win, 2);
    for name in [zip.file_name().unwrap(), tar.file_name().unwrap(), std::ffi::OsStr::new("SHA256SUMS")] {
        let (a, b) = (std::fs::read(dist.join(name)).unwrap(), std::fs::read(again.join(name)).unwrap());
        assert!(a == b, "{} differs between two runs of .ci/release", name.to_string_lossy());
    }
    let _ = std::fs::remove_dir_all(&dist);
    let _ = std::fs::remove_dir_all(&again);
}
