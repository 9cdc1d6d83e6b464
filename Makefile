# SAMPLE-3D in C.  See README.md.
#
#   make            all programs, in $(BUILD)/bin
#   make check      build and run every test (tests/run.sh)
#   make asan       the same under address and undefined-behaviour sanitizers
#   make bench      performance figures (tests/bench/*.sh)
#   make fuzz       libFuzzer run of every reader, FUZZ_SECONDS each (clang)
#   make run        the bundled example end to end
#   make install PREFIX=/usr/local
#   make NO_X11=1   build without the X11 preview
#
# Layout: src/lib/ is the static library, one folder per layer (system,
# numerics, geometry, drawing, formats; HACKING.md); src/splat, src/bleach, src/etch are one program each (every .c
# in the folder, main in main.c); src/plot/ holds one program per file,
# plus shared plot modules named plot_*.c.  Programs and tests are found by
# wildcard, so adding a file needs no change here.

BUILD   ?= build
CC      ?= cc
OPT     ?= -O2
CFLAGS  ?= $(OPT) -g
WARN     = -std=c11 -Wall -Wextra -Wshadow -Wstrict-prototypes -Wmissing-prototypes \
           -Wno-unused-parameter
ifdef WERROR
WARN    += -Werror
endif
LIB_DIRS := $(sort $(dir $(wildcard src/lib/*/*.c src/lib/*/*.h)))
CPPFLAGS += -D_XOPEN_SOURCE=700 $(patsubst %/,-I%,$(LIB_DIRS))
LDLIBS   = -lm -lpthread
PREFIX  ?= /usr/local

# X11 preview: detected by compiling a tiny program; NO_X11=1 turns it off.
ifeq ($(NO_X11),)
HAVE_X11 := $(shell printf '\043include <X11/Xlib.h>\nint main(void){return XOpenDisplay(0)!=0;}\n' \
	| $(CC) -x c - -o /dev/null -lX11 >/dev/null 2>&1 && echo yes)
endif
ifeq ($(HAVE_X11),yes)
X11_CPPFLAGS = -DHAVE_X11
X11_LIBS     = -lX11
endif
# every link gets it: the library's preview module may be pulled in by any
# program or test that draws
LDLIBS  += $(X11_LIBS)

LIB_SRC  := $(wildcard src/lib/*/*.c)
LIB_OBJ  := $(LIB_SRC:%.c=$(BUILD)/%.o)
LIB      := $(BUILD)/libsample3d.a

DIR_PROGS  := $(foreach p,splat bleach etch etch2d measure femwin calibfit stitch,$(if $(wildcard src/$(p)/main.c),$(p)))
PLOT_SRC   := $(wildcard src/plot/*.c)
PLOT_SHARE := $(filter src/plot/plot_%,$(PLOT_SRC))
PLOT_PROGS := $(notdir $(basename $(filter-out $(PLOT_SHARE),$(PLOT_SRC))))
PLOT_SHARE_OBJ := $(PLOT_SHARE:%.c=$(BUILD)/%.o)
PROGS    := $(DIR_PROGS) $(PLOT_PROGS)
DRIVERS  := sample3D sample2D fem calib
BINS     := $(PROGS:%=$(BUILD)/bin/%) $(DRIVERS:%=$(BUILD)/bin/%) $(BUILD)/bin/etchopts.sh $(BUILD)/bin/tile.sh

# C unit tests: tests/<area>/*.c, each linked with the library and with the
# objects of src/<area>/ other than main.o (so tests can call into etch).
TEST_SRC := $(wildcard tests/*/*.c)
TEST_BIN := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)

.PHONY: all check asan bench run install clean regen fuzz
all: $(BINS) $(TEST_BIN)

$(BUILD)/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(X11_CPPFLAGS) $(WARN) $(CFLAGS) -MMD -MP -c -o $@ $<

$(LIB): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	$(AR) rcs $@ $^

define dir_prog
$(1)_OBJ := $$(patsubst %.c,$(BUILD)/%.o,$$(wildcard src/$(1)/*.c))
$(BUILD)/bin/$(1): $$($(1)_OBJ) $(LIB)
	@mkdir -p $$(dir $$@)
	$$(CC) $$(CFLAGS) $$(LDFLAGS) -o $$@ $$($(1)_OBJ) $(LIB) $$(LDLIBS)
endef
$(foreach p,$(DIR_PROGS),$(eval $(call dir_prog,$(p))))

$(BUILD)/bin/%: $(BUILD)/src/plot/%.o $(PLOT_SHARE_OBJ) $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $< $(PLOT_SHARE_OBJ) $(LIB) $(LDLIBS)

# the drivers (POSIX sh), and the etch options sample3D and fem share,
# which they source from beside themselves (not a program: not executable)
$(DRIVERS:%=$(BUILD)/bin/%): $(BUILD)/bin/%: scripts/%.sh
	@mkdir -p $(dir $@)
	cp $< $@
	chmod +x $@

$(BUILD)/bin/etchopts.sh $(BUILD)/bin/tile.sh: $(BUILD)/bin/%.sh: scripts/%.sh
	@mkdir -p $(dir $@)
	cp $< $@
	chmod -x $@

# tests/<area>/<name>.c -> $(BUILD)/tests/<area>/<name>
.SECONDEXPANSION:
$(BUILD)/tests/%: tests/%.c $(LIB) $$(filter-out %/main.o,$$(patsubst %.c,$(BUILD)/%.o,$$(wildcard src/$$(firstword $$(subst /, ,$$*))/*.c)))
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(X11_CPPFLAGS) $(WARN) $(CFLAGS) $(LDFLAGS) -Isrc/$(firstword $(subst /, ,$*)) -o $@ $< \
		$(filter-out %/main.o,$(patsubst %.c,$(BUILD)/%.o,$(wildcard src/$(firstword $(subst /, ,$*))/*.c))) \
		$(LIB) $(LDLIBS)

check: all
	@sh tests/run.sh $(BUILD)

ASAN_VARS = BUILD=build-asan OPT=-O1 \
	CFLAGS="-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined" \
	LDFLAGS="-fsanitize=address,undefined"
# the sanitizers slow the programs 3-10x: the whole-pipeline tests (every
# example end to end) get more than run.sh's 600 s default
asan:
	$(MAKE) -j2 $(ASAN_VARS) all
	TEST_TIMEOUT=$${TEST_TIMEOUT:-2400} $(MAKE) $(ASAN_VARS) check

bench: all
	@sh tests/bench/run.sh $(BUILD)

# every file reader under libFuzzer (tests/fuzz/targets/fuzz.sh, HACKING.md)
FUZZ_SECONDS ?= 60
fuzz:
	sh tests/fuzz/targets/fuzz.sh run build-fuzz $(FUZZ_SECONDS)

run: all
	@cd examples/contact && PATH="$(CURDIR)/$(BUILD)/bin:$$PATH" sh ./run.sh
	@echo "make run: the pictures are in examples/contact/out/bake and examples/contact/out/nobake (profile.ps, cut.ps, image.ps)"

regen: all
	@sh tests/regen.sh $(BUILD)

install: all
	mkdir -p $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/man/man1 $(DESTDIR)$(PREFIX)/share/man/man5
	for p in $(PROGS); do cp $(BUILD)/bin/$$p $(DESTDIR)$(PREFIX)/bin/; done
	for d in $(DRIVERS); do cp scripts/$$d.sh $(DESTDIR)$(PREFIX)/bin/$$d && \
		chmod +x $(DESTDIR)$(PREFIX)/bin/$$d; done
	cp scripts/etchopts.sh $(DESTDIR)$(PREFIX)/bin/etchopts.sh
	chmod 644 $(DESTDIR)$(PREFIX)/bin/etchopts.sh
	cp scripts/tile.sh $(DESTDIR)$(PREFIX)/bin/tile.sh
	chmod 644 $(DESTDIR)$(PREFIX)/bin/tile.sh
	cp man/man1/*.1 $(DESTDIR)$(PREFIX)/share/man/man1/
	cp man/man5/*.5 $(DESTDIR)$(PREFIX)/share/man/man5/

clean:
	rm -rf build build-asan build-fuzz

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
