"""Prints where `cmake --install` puts the package rbsim/ for an install prefix, relative to it
(python/CMakeLists.txt runs it at install time with the module's interpreter):
usage: python3 site_dir.py PREFIX

The first folder this interpreter searches that lies in PREFIX/lib: its site folders
(site.getsitepackages(): on Debian /usr/local/lib/python3.X/dist-packages for /usr/local,
/usr/lib/python3/dist-packages for /usr), then the user's (site.getusersitepackages():
~/.local/lib/python3.X/site-packages). For any other prefix, sysconfig's posix_prefix scheme,
PREFIX/lib/python3.X/site-packages: the folder a venv at PREFIX, or PYTHONUSERBASE=PREFIX,
searches. (Debian's deb_system scheme gives lib/python3/dist-packages, which its python3 searches
for /usr alone; its default posix_local gives PREFIX/local/lib/..., which it searches for /usr alone.)"""
import os
import site
import sys
import sysconfig


def site_dir(prefix):
    prefix = os.path.abspath(prefix)
    searched = list(site.getsitepackages()) if hasattr(site, "getsitepackages") else []
    searched.append(site.getusersitepackages())
    for folder in searched:
        relative = os.path.relpath(os.path.abspath(folder), prefix)
        if relative.split(os.sep)[0] in ("lib", "lib64"):
            return relative
    path = sysconfig.get_path("platlib", "posix_prefix", vars={"base": prefix, "platbase": prefix})
    return os.path.relpath(path, prefix)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__.split("\n\n")[0])
    print(site_dir(sys.argv[1]))
