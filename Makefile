# Conveniences around the scripts (the README's two commands are scripts/demo.sh and
# scripts/test.sh, which need nothing installed beforehand).
.PHONY: all demo test bench clean

all:
	@scripts/build.sh

demo:
	@scripts/demo.sh

test:
	@scripts/test.sh

bench: all
	build/objektiv-bench
	bench/cornell.sh

clean:
	rm -rf build out
